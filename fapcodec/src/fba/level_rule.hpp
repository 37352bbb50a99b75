// How one FAP's values round to levels (docs/fba.md 2, "Quantisation" and "Legal ranges"): the
// standard's rounding, the second choice when a value lies exactly half way, and the cap that
// keeps a value inside its legal range from a level beyond it. The planner rounds every value of
// every group, so what depends only on the FAP's step and legal range is worked out once per
// group, and the division is a multiplication by a precomputed reciprocal. Private to fapcodec.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "fba/fba_quant.hpp"
#include "fba/level_chooser.hpp"

namespace fapc::fba {

class LevelRule {
 public:
  LevelRule(std::int64_t step, std::int64_t legal)
      : step_(step),
        half_(step / 2),
        legal_(legal),
        cap_(largest_legal_level(legal, step)),
        even_(step % 2 == 0 && step != 0),
        reciprocal_(step >= 2 ? std::numeric_limits<std::uint64_t>::max() / static_cast<std::uint64_t>(step) + 1 : 0) {}

  std::int64_t step() const { return step_; }

  // Every lattice point within half a step of `value` (a FAP value: an int32) is a correct
  // reconstruction: one, or two when the value lies exactly half way (even steps only);
  // level_chooser.hpp picks between two. A value within half a step of 0 is always sent as 0,
  // so that a FAP the mask fitter leaves out of the next group shows 0 to players either way
  // (mask_fitter.hpp). A value inside its legal range is never given a level beyond it: one step
  // closer to 0 instead.
  LevelOptions options(std::int64_t value) const {
    const std::int64_t magnitude = value < 0 ? -value : value;
    const bool inside = magnitude <= legal_;
    const std::int64_t nearest = nearest_level(value, magnitude, inside);
    LevelOptions options{nearest, nearest};
    if (even_ && 2 * std::llabs(value - nearest * step_) == step_ && magnitude > half_)
      options.other = value > nearest * step_ ? nearest + 1 : nearest - 1;
    if (inside && std::llabs(options.other) > cap_) options.other = nearest;
    return options;
  }
  // options(value).nearest.
  std::int64_t nearest(std::int64_t value) const {
    const std::int64_t magnitude = value < 0 ? -value : value;
    return nearest_level(value, magnitude, magnitude <= legal_);
  }

 private:
  // quantise(value, step), capped inside the legal range.
  std::int64_t nearest_level(std::int64_t value, std::int64_t magnitude, bool inside) const {
    std::int64_t nearest = value;
    if (step_ > 1) {
      const std::int64_t level = magnitude <= half_ ? 0 : divide(magnitude + half_);
      nearest = value < 0 ? -level : level;
    }
    return inside ? std::clamp(nearest, -cap_, cap_) : nearest;
  }
  // n / step for 0 <= n < 2^32 and step >= 2: with c = ceil(2^64 / step), floor(n c / 2^64) is
  // the quotient of every 32-bit n (Lemire, Kaser and Kurz, "Faster remainder by direct
  // computation", 2019). A value's magnitude plus half a step stays below 2^32.
  std::int64_t divide(std::int64_t n) const {
    return static_cast<std::int64_t>((static_cast<Wide>(reciprocal_) * static_cast<std::uint64_t>(n)) >> 64);
  }

  __extension__ typedef unsigned __int128 Wide;  // GCC and Clang; __extension__ keeps -Wpedantic quiet

  std::int64_t step_, half_, legal_, cap_;
  bool even_;
  std::uint64_t reciprocal_;
};

}  // namespace fapc::fba

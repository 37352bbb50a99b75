// Deterministic synthetic FAP sequences for the codec tests (the libFLAC habit: generate inputs
// instead of committing binaries): random masks that change now and then, random walks with
// occasional jumps, rests at 0 (where the encoder may fit masks), gaps in the numbering, FAP 1/2
// fields.
#pragma once

#include <algorithm>
#include <random>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc::test {

struct SequenceShape {
  int frames = 40;
  int quant = 1;     // values stay codable at this fap_quant
  bool gaps = true;  // skip frames now and then
  bool mask_changes = true;
  bool high_level = true;  // FAP 1 and FAP 2 sometimes
};

inline FapSequence random_sequence(std::mt19937& rng, const SequenceShape& shape) {
  const auto pick = [&rng](int low, int high) { return std::uniform_int_distribution<int>(low, high)(rng); };
  FapSequence sequence;
  sequence.name = "random";
  sequence.fps = pick(1, 255);
  std::bitset<kFapCount> mask;
  const auto new_mask = [&] {
    mask.reset();
    const int density = pick(0, 100);
    for (int fap = 3; fap <= kFapCount; ++fap) mask.set(static_cast<std::size_t>(fap - 1), pick(0, 99) < density);
    if (shape.high_level) {
      mask.set(0, pick(0, 3) == 0);
      mask.set(1, pick(0, 3) == 0);
    }
  };
  new_mask();
  std::array<std::int64_t, kFapCount> walk{};
  std::int64_t number = 0;
  for (int k = 0; k < shape.frames; ++k) {
    if (shape.mask_changes && pick(0, 12) == 0) new_mask();
    FapFrame frame;
    frame.number = number;
    number += 1 + (shape.gaps && pick(0, 6) == 0 ? pick(1, 40) : 0);
    frame.mask = mask;
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const std::size_t i = static_cast<std::size_t>(fap - 1);
      const std::int64_t qp = fap_table()[i].quant_step;
      // The largest |value| any range carries is 1860 steps of QP (1860 itself at fap_quant 0).
      const std::int64_t bound = shape.quant == 0 ? 1800 : 1800 * qp;
      std::int64_t& v = walk[i];
      v += pick(0, 20) == 0 ? pick(-900, 900) * qp : pick(-3, 3) * qp + pick(-2, 2);
      if (pick(0, 15) == 0) v = pick(-1, 1) * qp / 2;  // back to rest, within half a step of 0
      v = std::clamp<std::int64_t>(v, -bound, bound);
      if (mask.test(i)) frame.values[i] = static_cast<std::int32_t>(v);
    }
    frame.viseme = {pick(0, 14), pick(0, 14), pick(0, 63), pick(0, 1)};
    frame.expression = {pick(0, 6), pick(0, 63), pick(0, 6), pick(0, 63), pick(0, 1), pick(0, 1)};
    sequence.frames.push_back(frame);
  }
  return sequence;
}

}  // namespace fapc::test

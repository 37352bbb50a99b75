#include "fba/mask_fitter.hpp"

#include <array>
#include <bitset>
#include <cstdint>
#include <cstdlib>

#include "fapc/codec/fba.hpp"
#include "fba/shown_values.hpp"

namespace fapc::fba {

namespace {

using Mask = std::bitset<kFapCount>;

std::size_t bit(int fap) { return static_cast<std::size_t>(fap - 1); }

// Each FAP's bit moved to its left/right partner's place; FAPs without a partner get 0. Partners
// are neighbours in the table (6 and 7, 19 and 20 ...), so this is two shifts.
class PartnerSwap {
 public:
  PartnerSwap() {
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (lr_partner(fap) == fap + 1) {
        first_.set(bit(fap));
        second_.set(bit(fap + 1));
      }
  }
  Mask operator()(const Mask& m) const { return ((m & first_) << 1) | ((m & second_) >> 1); }

 private:
  Mask first_, second_;  // the lower and the higher FAP of each pair
};

}  // namespace

// Per frame, the FAPs that are free (see the header). A FAP is near zero in a frame when 0 is
// within tolerance of what every player shows: the value it holds (a present FAP shows its value
// to all three players, which is also what it holds) and, when it is absent, its partner's value.
MaskPlanner::MaskPlanner(int quant) {
  for (int fap = 3; fap <= kFapCount; ++fap) tolerance_[bit(fap)] = fba_tolerance(fap, quant);
  for (int fap = 3; fap <= kFapCount; ++fap) low_level_.set(bit(fap));
  was_near_ = low_level_;  // before the first frame: the neutral face
}

void MaskPlanner::add(const FapFrame& frame) {
  static const PartnerSwap swap;
  // Which values lie beyond their tolerance, gathered into words without a branch (a loop over
  // the bitset's proxies costs a read and a write of its word per FAP); a masked FAP's bit is
  // its value's, an absent one keeps what it held.
  std::uint64_t low = 0, high = 0;  // FAPs 1..64, 65..68
  for (std::size_t i = bit(3); i < 64; ++i)
    low |= static_cast<std::uint64_t>(std::llabs(frame.values[i]) > tolerance_[i]) << i;
  for (std::size_t i = 64; i < kFapCount; ++i)
    high |= static_cast<std::uint64_t>(std::llabs(frame.values[i]) > tolerance_[i]) << (i - 64);
  const Mask far = (Mask(high) << 64) | Mask(low);
  holds_far_ = (holds_far_ & ~frame.mask) | (far & frame.mask & low_level_);
  const Mask near = low_level_ & ~holds_far_ & ~(swap(holds_far_ & frame.mask) & ~frame.mask);
  plan_.free.push_back(near & was_near_ & ~swap(low_level_ & ~near));
  plan_.ahead.push_back(frame.mask);
  was_near_ = near;
}

MaskPlanner::Plan MaskPlanner::finish() && {
  // ahead[k]: per FAP, the input's bit in the first frame from k on where the FAP is not free (0
  // if it is free to the end). Choosing it at a change of mask puts off the next change.
  Mask next;
  for (std::size_t k = plan_.free.size(); k-- > 0;) {
    next = (next & plan_.free[k]) | (plan_.ahead[k] & ~plan_.free[k]);
    plan_.ahead[k] = next;
  }
  return std::move(plan_);
}

void MaskFitter::fit(FapFrame& frame) {
  const std::size_t k = next_++;
  const Mask& free = plan_.free[k];
  if (k == 0 || ((mask_ ^ frame.mask) & ~free).any()) mask_ = plan_.ahead[k];
  const Mask filled = mask_ & ~frame.mask;
  if (filled.any())
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (filled.test(bit(fap))) frame.values[bit(fap)] = 0;
  frame.mask = mask_;
}

std::vector<FapFrame> fit_masks(std::span<const FapFrame> frames, int quant) {
  MaskPlanner planner(quant);
  for (const FapFrame& frame : frames) planner.add(frame);
  MaskFitter fitter(std::move(planner).finish());
  std::vector<FapFrame> coded;
  coded.reserve(frames.size());
  for (const FapFrame& frame : frames) fitter.fit(coded.emplace_back(frame));
  return coded;
}

}  // namespace fapc::fba

#include "fba/mask_fitter.hpp"

#include <array>
#include <bitset>
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

// Per frame, the FAPs that are free (see the header). A FAP is near zero in a frame when 0 is
// within tolerance of what every player shows: the value it holds (a present FAP shows its value
// to all three players, which is also what it holds) and, when it is absent, its partner's value.
std::vector<Mask> free_bits(std::span<const FapFrame> frames, int quant) {
  std::array<std::int64_t, kFapCount> tolerance{};
  for (int fap = 3; fap <= kFapCount; ++fap) tolerance[bit(fap)] = fba_tolerance(fap, quant);
  Mask low_level;
  for (int fap = 3; fap <= kFapCount; ++fap) low_level.set(bit(fap));
  const PartnerSwap swap;
  std::vector<Mask> free(frames.size());
  Mask holds_far;                    // FAPs whose held value is beyond tolerance
  Mask was_near = low_level;         // before the first frame: the neutral face
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const FapFrame& frame = frames[k];
    for (std::size_t i = bit(3); i < kFapCount; ++i)
      if (frame.mask[i]) holds_far[i] = std::llabs(frame.values[i]) > tolerance[i];
    const Mask near = low_level & ~holds_far & ~(swap(holds_far & frame.mask) & ~frame.mask);
    free[k] = near & was_near & ~swap(low_level & ~near);
    was_near = near;
  }
  return free;
}

}  // namespace

std::vector<FapFrame> fit_masks(std::span<const FapFrame> frames, int quant) {
  const std::vector<Mask> free = free_bits(frames, quant);
  // ahead[k]: per FAP, the input's bit in the first frame from k on where the FAP is not free (0
  // if it is free to the end). Choosing it at a change of mask puts off the next change.
  std::vector<Mask> ahead(frames.size());
  Mask next;
  for (std::size_t k = frames.size(); k-- > 0;) {
    next = (next & free[k]) | (frames[k].mask & ~free[k]);
    ahead[k] = next;
  }
  std::vector<FapFrame> coded(frames.begin(), frames.end());
  Mask mask;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (k == 0 || ((mask ^ frames[k].mask) & ~free[k]).any()) mask = ahead[k];
    const Mask filled = mask & ~frames[k].mask;
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (filled.test(bit(fap))) coded[k].values[bit(fap)] = 0;
    coded[k].mask = mask;
  }
  return coded;
}

}  // namespace fapc::fba

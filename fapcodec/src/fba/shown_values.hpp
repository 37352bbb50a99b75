// What players show of a FAP that a frame leaves out. Three rules are in use (docs/fba.md
// section 2, "Masks"): a player that holds the FAP's last value (the MPEG-4 decoder model,
// docs/fba-bitstream.md section 8); one that shows it at 0 (Xface, whose frames start all zero);
// and the reference decoder, which copies a FAP present on one side of the face into its absent
// left/right partner (section 12.6, D6) and otherwise leaves it at 0. The mask fitter changes masks
// only where all three agree, and verification checks all three. Private to fapcodec.
#pragma once

#include <array>
#include <cstdint>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc::fba {

// The FAP on the other side of the face (stretch_l_cornerlip and stretch_r_cornerlip ...), 0 if
// none.
int lr_partner(int fap);

// Follows a sequence frame by frame for the player that holds values.
class HeldValues {
 public:
  void advance(const FapFrame& frame) {
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (frame.has(fap)) held_[index(fap)] = frame.value(fap);
  }
  std::int64_t held(int fap) const { return held_[index(fap)]; }  // 0 before it is first sent

 private:
  static std::size_t index(int fap) { return static_cast<std::size_t>(fap - 1); }
  std::array<std::int32_t, kFapCount> held_{};
};

inline std::int64_t shown_as_zero(const FapFrame& frame, int fap) { return frame.has(fap) ? frame.value(fap) : 0; }

inline std::int64_t shown_with_partner(const FapFrame& frame, int fap) {
  if (frame.has(fap)) return frame.value(fap);
  const int partner = lr_partner(fap);
  return partner != 0 && frame.has(partner) ? frame.value(partner) : 0;
}

}  // namespace fapc::fba

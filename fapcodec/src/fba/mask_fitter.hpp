// The masks the encoder codes (docs/fba.md 2, "Masks"). Masks travel only in intra planes, so a
// change of mask costs an intra plane: four range lists and fresh adaptive models, some 1,500 to
// 2,500 bits in the Xface files, whose eyelids appear in the mask only while they blink. Where it
// changes nothing a player shows, the encoder may send a FAP the input leaves out (as 0) or leave
// out one the input sends: the fitter uses that freedom to change the mask as seldom as it can,
// and leaves out FAPs that stay at 0.
//
// A FAP is free in frame k when 0 is within half a step of what every player shows of it
// (shown_values.hpp) in frames k - 1 and k, and of its left/right partner in frame k. So a player
// that holds values shows 0 either way (the FAP was 0 before), one that shows absent FAPs at 0
// does too, and so does the reference decoder, which would copy the partner into it. Where a FAP
// is not free, the input's mask bit stands. Private to fapcodec.
#pragma once

#include <bitset>
#include <span>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc::fba {

using FapMask = std::bitset<kFapCount>;

// What fitting needs to know of the whole sequence, frame by frame: which FAPs are free, and per
// FAP the input's bit in the first frame from there on where the FAP is not free (the bit a change
// of mask should choose, to put off the next change). Gathered by one pass over the frames (add),
// then a backward pass over the two bitsets (finish): 32 bytes a frame, never the frames.
class MaskPlanner {
 public:
  explicit MaskPlanner(int quant);  // fap_quant, which sets the tolerance (half a step)
  void add(const FapFrame& frame);
  struct Plan {
    std::vector<FapMask> free, ahead;
  };
  Plan finish() &&;

 private:
  std::array<std::int64_t, kFapCount> tolerance_{};
  FapMask low_level_, holds_far_, was_near_;
  Plan plan_;  // ahead holds the input's masks until finish
};

// The frames as coded, one at a time and in order: the masks fitted, FAPs sent where the input
// leaves them out carry 0.
class MaskFitter {
 public:
  explicit MaskFitter(MaskPlanner::Plan plan) : plan_(std::move(plan)) {}
  // Frame k of the sequence the plan was made from, made into the frame as coded (in place: the
  // encoder copies each frame once, into its window).
  void fit(FapFrame& frame);

 private:
  MaskPlanner::Plan plan_;
  std::size_t next_ = 0;
  FapMask mask_;
};

// The whole sequence at once (both passes).
std::vector<FapFrame> fit_masks(std::span<const FapFrame> frames, int quant);

}  // namespace fapc::fba

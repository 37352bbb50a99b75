// Frames kept compactly between the FBA encoder's two passes, so that a streamed compile renders
// each frame once and a streamed conversion decodes its input once (docs/architecture.md,
// "Streaming"). The encoder must see every frame before it codes the first (it plans masks over
// the whole sequence), so the frames are needed twice; rendering or decoding a frame costs about a
// microsecond, replaying it from the tape a few dozen nanoseconds. A frame costs a byte or two per
// masked FAP: its number and the values' differences from the previous frame, as variable-length
// integers. A tape that would outgrow its budget is dropped (the caller makes the frames again),
// so memory stays bounded whatever the animation. The tape is held in blocks that the replay gives
// back as it passes them: the second pass's outputs grow while the tape shrinks. Private to the
// pipeline.
#pragma once

#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc::pipeline {

// The most bytes the frames may take on the tape between the passes: a byte or two per masked FAP
// and frame, so some 10^6 frames of every FAP or 10^7 of a few; beyond, the second pass makes the
// frames again.
inline constexpr std::size_t kFrameTapeBudget = std::size_t{64} << 20;

class FrameTape {
  // A mask's slots, worked out once per mask rather than per frame.
  struct Slots {
    Slots() { take({}); }
    std::bitset<kFapCount> mask;
    std::array<std::uint8_t, kFapCount> index{};  // the masked slots, ascending
    std::size_t count = 0;
    std::array<std::int32_t, kFapCount> outside{};  // -1 for a slot outside the mask, else 0
    void take(const std::bitset<kFapCount>& new_mask);
    // Whether every slot and field outside the mask is at rest (0, default fields).
    bool at_rest_outside(const FapFrame& frame) const;
  };

 public:
  // The most bytes the tape may hold (frames beyond drop it).
  explicit FrameTape(std::size_t budget) : budget_(budget) {}

  // Appends the frame; false (and the tape emptied for good) once the budget is exceeded.
  bool record(const FapFrame& frame);
  bool dropped() const { return dropped_; }
  std::size_t bytes() const { return bytes_; }

  // The recorded frames again, in order, each equal in every field to the one recorded. Each
  // block is freed as the player leaves it, unless the tape is `kept` for another playing.
  class Player {
   public:
    Player(FrameTape& tape, bool kept) : tape_(tape), kept_(kept) {}
    // The next frame, valid until the next call (it is rebuilt in place from its differences).
    const FapFrame& next();

   private:
    FrameTape& tape_;
    bool kept_;
    std::size_t block_ = 0;
    std::size_t at_ = 0;  // in that block
    FapFrame frame_;      // the last frame played
    Slots slots_;         // of its mask
  };
  Player play(bool kept = false) { return Player(*this, kept); }

 private:
  // A block's size, and the most bytes one frame can take (a flag, the mask, a number's
  // difference, and differences of 32-bit values for 68 FAPs and 10 fields), so that no frame is
  // split across blocks: 1 + 9 + 10 + 78 * 5 = 410.
  static constexpr std::size_t kBlockBytes = std::size_t{1} << 20;
  static constexpr std::size_t kMostFrameBytes = 512;

  struct Block {
    std::unique_ptr<std::uint8_t[]> bytes;  // kBlockBytes
    std::size_t size = 0;                   // of them recorded
  };
  void drop();

  std::size_t budget_;
  bool dropped_ = false;
  std::size_t bytes_ = 0;      // recorded, over every block
  std::vector<Block> blocks_;  // the last is being filled
  FapFrame previous_;          // the last frame recorded: values are coded as differences from it
  Slots slots_;                // of its mask
};

}  // namespace fapc::pipeline

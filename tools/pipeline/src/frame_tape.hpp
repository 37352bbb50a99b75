// Rendered frames kept compactly between the FBA encoder's two passes, so that a streamed compile
// renders each frame once (docs/architecture.md, "Streaming"). The encoder must see every frame
// before it codes the first (it plans masks over the whole sequence), so the frames are needed
// twice; rendering a frame costs about a microsecond, replaying it from the tape a few dozen
// nanoseconds. A frame costs a byte or two per masked FAP: its number and the values' differences
// from the previous frame, as variable-length integers. A tape that would outgrow its budget is
// dropped (the caller renders the frames again), so memory stays bounded whatever the animation.
// Private to the pipeline.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc::pipeline {

class FrameTape {
 public:
  // The most bytes the tape may hold (frames beyond drop it).
  explicit FrameTape(std::size_t budget) : budget_(budget) {}

  // Appends the frame; false (and the tape emptied for good) once the budget is exceeded.
  bool record(const FapFrame& frame);
  bool dropped() const { return dropped_; }
  std::size_t bytes() const { return bytes_.size(); }

  // The recorded frames again, in order, each equal in every field to the one recorded.
  class Player {
   public:
    explicit Player(const FrameTape& tape) : tape_(tape) {}
    FapFrame next();

   private:
    const FrameTape& tape_;
    std::size_t at_ = 0;
    FapFrame previous_;
  };
  Player play() const { return Player(*this); }

 private:
  void put(std::uint64_t v);
  void put_signed(std::int64_t v) { put((static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63)); }

  std::size_t budget_;
  bool dropped_ = false;
  std::vector<std::uint8_t> bytes_;
  FapFrame previous_;  // the last frame recorded: values are coded as differences from it
};

}  // namespace fapc::pipeline

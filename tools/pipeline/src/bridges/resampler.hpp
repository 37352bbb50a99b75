// Samples at the tracker's times (irregular, as OpenFace and Live Link Face write them) to frames
// on the grid of --fps: frame k is at k / fps seconds after the first sample, its values linearly
// interpolated between the samples on either side. The frames are made as the samples arrive, so
// no sample is kept but the previous one, and the frame limit is checked before each frame is made.
#pragma once

#include <bitset>
#include <cstdint>

#include "fapc/codec/fap_sequence.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/vocabulary/shape_basis.hpp"

namespace fapc::pipeline::bridges {

class Resampler {
 public:
  // `faps`: the FAPs every frame carries (those the file's columns drive).
  Resampler(int fps, std::bitset<kFapCount> faps, const Limits& limits, FapSequence& out)
      : fps_(fps), faps_(faps), limits_(limits), out_(out) {}

  // A sample at `time` seconds (from the file's own clock); times never decrease (the caller
  // checks). `where` places a limit error.
  Status push(double time, const vocabulary::FapVector& values, const Location& where);
  bool empty() const { return !started_; }

 private:
  void emit(std::int64_t frame, const vocabulary::FapVector& values);

  int fps_;
  std::bitset<kFapCount> faps_;
  const Limits& limits_;
  FapSequence& out_;
  bool started_ = false;
  double first_time_ = 0;
  double previous_time_ = 0;  // from the first sample
  vocabulary::FapVector previous_{};
  std::int64_t next_frame_ = 0;
};

}  // namespace fapc::pipeline::bridges

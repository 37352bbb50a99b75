// Writes the syntax of a face-only FBA stream (docs/fba-bitstream.md sections 5 and 6.7) from the
// planner's decisions: object start code, planes (plane header, temporal header, masks, the four
// range lists, arithmetic-coded segments), stuffing and end code. Private to fapcodec.
#pragma once

#include <optional>
#include <vector>

#include "fapc/codec/fba.hpp"
#include "fba/arith_encoder.hpp"
#include "fba/face_state.hpp"
#include "fba/gop_planner.hpp"

namespace fapc::fba {

class PlaneWriter {
 public:
  // `window`: the planner's window of frames (GopPlanner); `fps`: the sequence's frame rate.
  PlaneWriter(const FrameWindow& window, int fps, const FbaEncodeOptions& options);

  // Every plane of the group, in order. The window holds the frame after the group unless the
  // group ends the sequence (a plane's skip count is the gap to the next frame).
  void write(const Gop& gop);
  // Room for this many planes' places, when the caller knows how many there will be (a long
  // stream's list of planes would otherwise be copied as it grows, twice its size at the peak).
  void reserve(std::size_t planes) { result_.planes.reserve(planes); }
  // Stuffing and the end code; the stream and where each plane went.
  EncodedFba finish();

 private:
  void write_plane(const Gop& gop, std::size_t k);
  void write_temporal_header(bool intra, std::int64_t skip);
  // Whether the plane just written, from `start` (its first bit) on, must grow so that players
  // read it (docs/fba.md 2, "End of a plane"); `last` for the plane before the end code.
  bool needs_padding(std::size_t start, bool last) const;
  void write_intra_face_header(const Gop& gop);
  void write_segments(const Gop& gop, std::size_t k, bool intra);

  const FrameWindow& frames_;  // the window
  FbaEncodeOptions options_;
  std::optional<std::int64_t> first_number_;  // of the sequence's first frame
  int fps_;
  BitWriter out_;
  ArithEncoder coder_{out_};
  FaceState state_;
  EncodedFba result_;
  std::size_t skip_flag_at_ = 0;  // bit position of the current plane's skip_frames flag
};

}  // namespace fapc::fba

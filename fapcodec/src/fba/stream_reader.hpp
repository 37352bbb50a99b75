// The stream level of the decoder (docs/fba-bitstream.md sections 5.1 to 5.3, 5.9): optional visual
// object sequence and visual object headers, the FBA object start code, then planes, each either
// following the previous one bit for bit (the reference encoder's layout) or introduced by
// stuffing and a plane start code, until the end code. Private to fapcodec.
#pragma once

#include <span>

#include "fapc/codec/fba.hpp"
#include "fba/body_reader.hpp"
#include "fba/decode_context.hpp"
#include "fba/face_reader.hpp"

namespace fapc::fba {

class StreamReader {
 public:
  // Without a sink the frames are kept in the result; with one, each goes to it.
  StreamReader(std::span<const std::uint8_t> bytes, const FbaDecodeOptions& options, FbaFrameSink sink = {});
  Result<DecodedFba> run();

 private:
  struct TemporalHeader {
    std::int64_t skip = 0;
    bool time_code = false;
    std::int64_t time_code_seconds = 0;
  };
  enum class Next { plane, end };

  Status read_stream_headers();
  void skip_user_data();
  // After a plane (or the object start code): a start code behind stuffing, or the next plane
  // right here. Errors on any start code other than plane and end codes, and at the end of data.
  Result<Next> next_part();
  Status read_plane();
  Status read_temporal_header(bool intra, TemporalHeader& header);
  void set_frame_rate(double rate);
  Diagnostic explain(const Diagnostic& error) const;
  void note_ranges(std::int64_t frame, std::int64_t byte, std::size_t bits);

  FbaDecodeOptions options_;
  DecodeContext c_;
  FaceState face_;
  BodyState body_;
  DecodedFba out_;
  FbaFrameSink sink_;
  std::int64_t next_number_ = 0;  // frame number of the next face plane without a time code
  // The first and last face planes' frame numbers, once there is one (the frames may not be kept).
  bool any_frame_ = false;
  std::int64_t first_number_ = 0, last_number_ = 0;
  bool body_warned_ = false;
  bool rate_change_warned_ = false;
};

}  // namespace fapc::fba

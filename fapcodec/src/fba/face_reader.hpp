// Reads the face part of a plane (docs/fba-bitstream.md sections 5.4 to 5.7, 6.7, 6.8): in intra
// planes fap_quant, the group masks and the range lists; then the viseme, expression and
// low-level segments, reconstructing values exactly as the encoder's closed loop did.
// Private to fapcodec.
#pragma once

#include "fapc/codec/fap_sequence.hpp"
#include "fba/decode_context.hpp"
#include "fba/face_state.hpp"

namespace fapc::fba {

class FaceReader {
 public:
  FaceReader(DecodeContext& context, FaceState& state) : c_(context), state_(state) {}

  // The intra-only fields: fap_quant, masks, coding type, range lists. Rebuilds the models.
  Status read_intra_header();
  // The segments of one plane, into `frame` (mask and values; the number is the caller's).
  Status read_values(bool intra, FapFrame& frame);

 private:
  Status read_masks();
  Status read_range_lists(const bool (&present)[kRangeListCount]);
  int read_field(int field, bool intra);

  DecodeContext& c_;
  FaceState& state_;
};

}  // namespace fapc::fba

// Parses the body (BAP) part of a plane far enough to step over it (docs/fba-bitstream.md
// section 5.8, appendix A): masks, range lists and the arithmetic-coded segment, whose length is
// only known by decoding it with the same models the encoder used. The values are not kept: fapc
// handles faces only. BAPs are addressed by their position in the group order, which is also the
// coding order, so their numbers are never needed. Private to fapcodec.
#pragma once

#include <array>
#include <vector>

#include "fba/adaptive_model.hpp"
#include "fba/decode_context.hpp"
#include "fba/fba_syntax.hpp"

namespace fapc::fba {

struct BodyState {
  bool started = false;
  int scaler = 1;
  std::array<bool, kBapCount> mask{};
  std::array<std::array<std::int32_t, kBapCount>, kRangeListCount> range{};
  std::array<std::array<bool, kBapCount>, kRangeListCount> range_set{};  // no defaults exist
  std::vector<AdaptiveModel> pred_models = std::vector<AdaptiveModel>(kBapCount);
};

class BodyReader {
 public:
  BodyReader(DecodeContext& context, BodyState& state) : c_(context), state_(state) {}
  Status skip(bool intra);

 private:
  Status read_intra_header();

  DecodeContext& c_;
  BodyState& state_;
};

}  // namespace fapc::fba

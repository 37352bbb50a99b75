#include "fba/body_reader.hpp"

namespace fapc::fba {

Status BodyReader::read_intra_header() {
  const int index = static_cast<int>(c_.in.read_bits(kBapQuantBits));
  state_.scaler = index == 0 ? 1 : kBapPredScale[static_cast<std::size_t>(index)];
  std::size_t at = 0;
  for (const int size : kBapGroupSizes) {
    if (auto status = c_.read_marker("before a BAP mask type"); !status) return status;
    const std::int64_t type_byte = c_.in.byte_offset();
    const auto type = c_.in.read_bits(kMaskTypeBits);
    if (type == kMaskListedInterpolate)
      return c_.error_at(codes::fba::undefined_bap_mask, type_byte, "BAP mask type 10 is not defined");
    for (int j = 0; j < size; ++j, ++at)
      state_.mask[at] = type == kMaskAll || (type == kMaskListed && c_.in.read_bit());
  }
  c_.in.read_bit();  // fba_suggested_gender
  const std::int64_t coding_type_byte = c_.in.byte_offset();
  if (c_.in.read_bit() == 1)
    return c_.error_at(codes::fba::dct_unsupported, coding_type_byte,
                       "BAP coding type 1 (DCT segments) is not supported");
  bool present[kRangeListCount];
  for (bool& flag : present) flag = c_.in.read_bit() == 1;
  for (int list = 0; list < kRangeListCount; ++list) {
    if (!present[list]) continue;
    at = 0;
    for (const int size : kBapGroupSizes) {
      for (int j = 0; j < size; ++j, ++at) {
        if (j % kMarkerEvery == 0)
          if (auto status = c_.read_marker("in a BAP range list"); !status) return status;
        if (!state_.mask[at]) continue;
        const auto magnitude =
            static_cast<std::int32_t>(c_.in.read_bits(kRangeValueBits)) * kRangeDelta / state_.scaler;
        const auto l = static_cast<std::size_t>(list);
        state_.range[l][at] = (list == kIntraMin || list == kPredMin) ? -magnitude : magnitude;
        state_.range_set[l][at] = true;
      }
    }
  }
  if (auto status = c_.check_inside("a body intra plane's header"); !status) return status;
  for (std::size_t b = 0; b < kBapCount; ++b) {
    if (!state_.mask[b]) continue;
    for (const auto& set : state_.range_set)
      if (!set[b])
        return c_.error_here(codes::fba::bap_range_missing,
                             "a masked BAP has no signalled range (body streams must send all four range lists)");
    state_.pred_models[b].reset(state_.range[kPredMax][b] - state_.range[kPredMin][b] + 1);
  }
  state_.started = true;
  return ok_status();
}

Status BodyReader::skip(bool intra) {
  if (intra) {
    if (auto status = read_intra_header(); !status) return status;
  } else if (!state_.started) {
    return c_.error_here(codes::fba::predictive_before_intra,
                         "a predictive body plane comes before the first intra body plane");
  }
  c_.coder.start();
  for (std::size_t b = 0; b < kBapCount; ++b) {
    if (!state_.mask[b]) continue;
    if (intra) {
      c_.coder.decode_uniform(state_.range[kIntraMax][b] - state_.range[kIntraMin][b] + 1);
    } else {
      state_.pred_models[b].update(c_.coder.decode(state_.pred_models[b]));
    }
  }
  return c_.finish_segment("BAP");
}

}  // namespace fapc::fba

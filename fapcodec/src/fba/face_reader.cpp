#include "fba/face_reader.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "fba/fba_quant.hpp"

namespace fapc::fba {

Status FaceReader::read_masks() {
  state_.mask.reset();
  for (const FapGroup& group : fap_groups()) {
    if (auto status = c_.read_marker("before a FAP mask type"); !status) return status;
    const auto type = static_cast<MaskType>(c_.in.read_bits(kMaskTypeBits));
    for (int fap = group.first_fap; fap <= group.last_fap; ++fap) {
      // Types 01 and 10 list one bit per FAP; 10 also lets a player interpolate the others, which
      // is the player's business (docs/fba-bitstream.md section 5.4).
      const bool on = type == kMaskAll || ((type == kMaskListed || type == kMaskListedInterpolate) && c_.in.read_bit());
      state_.mask.set(FaceState::index(fap), on);
    }
  }
  return ok_status();
}

Status FaceReader::read_range_lists(const bool (&present)[kRangeListCount]) {
  for (int list = 0; list < kRangeListCount; ++list) {
    if (!present[list]) continue;
    for (const FapGroup& group : fap_groups()) {
      const int first = std::max(group.first_fap, kFirstLowLevelFap);
      for (int fap = first; fap <= group.last_fap; ++fap) {
        if ((fap - first) % kMarkerEvery == 0)
          if (auto status = c_.read_marker("in a FAP range list"); !status) return status;
        if (!state_.mask.test(FaceState::index(fap))) continue;
        state_.set_range(static_cast<RangeList>(list), fap, static_cast<int>(c_.in.read_bits(kRangeValueBits)));
      }
    }
  }
  return ok_status();
}

Status FaceReader::read_intra_header() {
  state_.fap_quant = static_cast<int>(c_.in.read_bits(kFapQuantBits));
  if (auto status = read_masks(); !status) return status;
  c_.in.read_bit();  // fba_suggested_gender: no effect on decoding
  const std::int64_t coding_type_byte = c_.in.byte_offset();
  if (c_.in.read_bit() == 1)
    return c_.error_at(codes::fba::dct_unsupported, coding_type_byte,
                       "FAP coding type 1 (DCT segments) is not supported: no public description of "
                       "its code tables exists");
  bool present[kRangeListCount];
  for (bool& flag : present) flag = c_.in.read_bit() == 1;
  // The first intra plane starts from the per-FAP default table; signalled lists overwrite it.
  if (!state_.ranges_initialised) {
    state_.set_default_ranges();
    state_.ranges_initialised = true;
  }
  if (auto status = read_range_lists(present); !status) return status;
  if (auto status = c_.check_inside("an intra plane's header"); !status) return status;
  state_.reset_models();
  state_.started = true;
  return ok_status();
}

int FaceReader::read_field(int field, bool intra) {
  const auto f = static_cast<std::size_t>(field);
  const int limit = state_.field_limit(field);
  const int step = state_.field_step(field);
  if (intra) {
    const int q = c_.coder.decode_uniform(limit + 1);
    state_.previous_fields[f] = static_cast<std::int32_t>(dequantise(q, step));
  } else {
    AdaptiveModel& model = state_.field_pred_models[f];
    const int s = c_.coder.decode(model);
    model.update(s);
    state_.previous_fields[f] += static_cast<std::int32_t>(dequantise(s - limit, step));
  }
  // Streams from older fapc versions (and from other encoders) may round 63 up to 64 at an even
  // step; prediction goes on from 64, but the frame gets the field's largest legal value.
  return std::min(state_.previous_fields[f], kLargestFieldValue);
}

Status FaceReader::read_values(bool intra, FapFrame& frame) {
  frame.mask = state_.mask;
  if (state_.mask.test(0)) {
    c_.coder.start();
    frame.viseme.select1 = read_field(0, intra);
    frame.viseme.select2 = read_field(1, intra);
    frame.viseme.blend = read_field(2, intra);
    if (auto status = c_.finish_segment("viseme"); !status) return status;
    frame.viseme.def = c_.in.read_bit();
  }
  if (state_.mask.test(1)) {
    c_.coder.start();
    frame.expression.select1 = read_field(3, intra);
    frame.expression.intensity1 = read_field(4, intra);
    frame.expression.select2 = read_field(5, intra);
    frame.expression.intensity2 = read_field(6, intra);
    if (auto status = c_.finish_segment("expression"); !status) return status;
    frame.expression.init_face = c_.in.read_bit();
    frame.expression.def = c_.in.read_bit();
  }
  const std::int64_t segment_byte = c_.in.byte_offset();
  c_.coder.start();
  bool overflow = false;
  const auto store = [&](std::size_t i, std::int64_t value) {
    // Predictions accumulate; only a corrupt or hostile stream walks them out of 32 bits.
    if (value > std::numeric_limits<std::int32_t>::max() || value < std::numeric_limits<std::int32_t>::min()) {
      overflow = true;
      value = 0;
    }
    state_.previous[i] = value;
    frame.values[i] = static_cast<std::int32_t>(value);
  };
  if (intra) {
    for (const std::size_t i : state_.coded) {
      const std::int32_t low = state_.range[kIntraMin][i];
      store(i, dequantise(c_.coder.decode_uniform(state_.range[kIntraMax][i] - low + 1) + low, state_.steps[i]));
    }
  } else {
    c_.coder.decode_and_count(state_.coded, state_.pred_models, [&](std::size_t i, int s) {
      store(i, state_.previous[i] + dequantise(s + state_.range[kPredMin][i], state_.steps[i]));
    });
  }
  if (auto status = c_.finish_segment("FAP"); !status) return status;
  if (overflow)
    return c_.error_at(codes::fba::value_overflow, segment_byte,
                       "a decoded FAP value overflows 32 bits (corrupt stream?)");
  return ok_status();
}

}  // namespace fapc::fba

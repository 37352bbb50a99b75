#include "fba/face_state.hpp"

namespace fapc::fba {

int FaceState::field_limit(int field) const {
  const int fixed = kFieldLimit[static_cast<std::size_t>(field)];
  if (fixed >= 0) return fixed;
  return fap_quant == 0 ? 63 : (63 + fap_quant / 2) / fap_quant;
}

void FaceState::set_default_ranges() {
  // Defaults are rounded up to a multiple of 60 before use (only FAP 63 changes, 680 -> 720).
  const auto round_up = [](int r) { return (r + kRangeDelta - 1) / kRangeDelta * kRangeDelta; };
  const int s = range_scaler();
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    const FapInfo& info = fap_table()[index(fap)];
    const std::int32_t intra = round_up(info.intra_range) / s;
    const std::int32_t pred = round_up(info.predictive_range) / s;
    range[kIntraMax][index(fap)] = intra;
    range[kIntraMin][index(fap)] = -intra;
    range[kPredMax][index(fap)] = pred;
    range[kPredMin][index(fap)] = -pred;
  }
}

void FaceState::set_range(RangeList list, int fap, int code) {
  const std::int32_t magnitude = code * kRangeDelta / range_scaler();
  range[list][index(fap)] = (list == kIntraMin || list == kPredMin) ? -magnitude : magnitude;
}

void FaceState::reset_models() {
  coded.clear();
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    steps[index(fap)] = step(fap);
    if (!mask.test(index(fap))) continue;
    coded.push_back(static_cast<std::uint8_t>(index(fap)));
    pred_models[index(fap)].reset(pred_max(fap) - pred_min(fap) + 1);
  }
  for (int field = 0; field < kCodedFieldCount; ++field) {
    const int fap = field < kVisemeFields ? 1 : 2;
    if (mask.test(index(fap))) field_pred_models[static_cast<std::size_t>(field)].reset(2 * field_limit(field) + 1);
  }
}

}  // namespace fapc::fba

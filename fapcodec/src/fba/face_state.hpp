// What encoder and decoder both keep about the face part of a stream between planes
// (docs/fba-bitstream.md section 8): the mask and fap_quant of the last intra plane, the persistent
// ranges, the adaptive P models, and the reconstructed values that predictive planes add to.
// Both sides drive it through the same calls, so they stay in step by construction.
// Private to fapcodec.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <vector>

#include "fapc/codec/fap_table.hpp"
#include "fba/adaptive_model.hpp"
#include "fba/fba_syntax.hpp"

namespace fapc::fba {

// The 5-bit range values of one intra plane: codes[list][fap - 1] for FAPs 3..68.
using RangeCodes = std::array<std::array<std::uint8_t, kFapCount>, kRangeListCount>;

struct FaceState {
  bool started = false;             // an intra plane has set masks, ranges and models
  bool ranges_initialised = false;  // explicit, unlike the reference (section 13, item 13)
  int fap_quant = 1;
  std::bitset<kFapCount> mask;
  // Ranges in quantised units, index fap - 1; [list] as RangeList.
  std::array<std::array<std::int32_t, kFapCount>, kRangeListCount> range{};
  std::array<AdaptiveModel, kFapCount> pred_models;
  std::array<AdaptiveModel, kCodedFieldCount> field_pred_models;
  std::array<std::int64_t, kFapCount> previous{};                // reconstructed values
  std::array<std::int32_t, kCodedFieldCount> previous_fields{};  // reconstructed fields
  // Set with the models at every intra plane, for the planes' inner loops: the masked FAPs
  // 3..68 (index fap - 1, ascending) and the quantiser step of every FAP.
  std::vector<std::uint8_t> coded;
  std::array<std::int64_t, kFapCount> steps{};

  // fap_quant as the range lists divide by it (1 when fap_quant is 0).
  int range_scaler() const { return fap_quant == 0 ? 1 : fap_quant; }
  std::int64_t step(int fap) const { return static_cast<std::int64_t>(fap_table()[index(fap)].quant_step) * fap_quant; }
  std::int32_t intra_min(int fap) const { return range[kIntraMin][index(fap)]; }
  std::int32_t intra_max(int fap) const { return range[kIntraMax][index(fap)]; }
  std::int32_t pred_min(int fap) const { return range[kPredMin][index(fap)]; }
  std::int32_t pred_max(int fap) const { return range[kPredMax][index(fap)]; }

  // FAP 1/2 fields: the largest intra symbol (14, 6, or B = (63 + q/2) / q for blends and
  // intensities), whether the field is quantised, and its step.
  int field_limit(int field) const;
  bool field_quantised(int field) const { return kFieldLimit[static_cast<std::size_t>(field)] < 0; }
  int field_step(int field) const { return field_quantised(field) ? fap_quant : 0; }

  // The per-FAP default table, used on the first intra plane before any list is applied.
  void set_default_ranges();
  // One entry of a range list: v * 60 / scaler, negated for the minimum lists.
  void set_range(RangeList list, int fap, int code);
  // At every intra plane, after its ranges: fresh P models for the masked FAPs and the fields,
  // and the coded list and steps.
  void reset_models();

  static std::size_t index(int fap) { return static_cast<std::size_t>(fap - 1); }
};

}  // namespace fapc::fba

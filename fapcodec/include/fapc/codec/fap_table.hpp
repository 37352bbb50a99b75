// The 68 MPEG-4 face animation parameters (ISO/IEC 14496-2 FAP table) as one data table, with the
// facial animation parameter units. Facts from the standard's table as recorded in
// docs/fap-table.md; the quantiser steps and default ranges are those of the reference codec.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/did_you_mean.hpp"  // edit_distance, closest_names

namespace fapc {

inline constexpr int kFapCount = 68;
inline constexpr int kFapGroupCount = 10;

// Facial animation parameter units: fractions of distances on the neutral face, or angles.
enum class Fapu { none, irisd, es, ens, mns, mw, au };

struct FapuInfo {
  Fapu unit;
  std::string_view name;        // "MNS"
  std::string_view definition;  // what it measures
};
const std::array<FapuInfo, 7>& fapu_table();
std::string_view fapu_name(Fapu unit);

struct FapInfo {
  int number;             // 1..68
  std::string_view name;  // standard name, e.g. "open_jaw"
  std::string_view description;
  Fapu unit;
  bool bidirectional;  // U (false) or B (true) in the standard's table
  std::string_view positive_motion;
  int group;             // 1..10
  int quant_step;        // QP of the reference codec; step is QP * fap_quant
  int intra_range;       // default I range in quantised units (symmetric: -r..r)
  int predictive_range;  // default P range in quantised units
  // The largest |value| in FAP units that an intra frame carries with default ranges at
  // fap_quant 1 (intra range rounded up to a multiple of 60, times QP). This is what the project
  // calls the FAP's legal range; renderers clamp to it. 0 for FAP 1 and 2.
  int legal_max() const;
};

// Index 0 is FAP 1.
const std::array<FapInfo, kFapCount>& fap_table();

const FapInfo* find_fap(int number);
const FapInfo* find_fap(std::string_view name);
// Accepts "open_jaw", "3", "fap3" and "FAP3": the forms users type.
const FapInfo* find_fap_by_name_or_number(std::string_view text);

// The standard names closest to `name` (edit distance), best first, for "did you mean" messages.
std::vector<std::string_view> closest_fap_names(std::string_view name, std::size_t how_many = 3);

// "unknown FAP name 'opn_jaw'; did you mean open_jaw, ...?"
std::string unknown_fap_message(std::string_view name);

// Group g (1..10) covers FAPs [first, last].
struct FapGroup {
  int number;
  int first_fap;
  int last_fap;
  std::string_view name;  // "jaw, chin, inner lip" ...
};
const std::array<FapGroup, kFapGroupCount>& fap_groups();

// Fields of FAP 1 (viseme) and FAP 2 (expression), in bitstream and .fap order.
inline constexpr int kVisemeFieldCount = 4;
inline constexpr int kExpressionFieldCount = 6;
std::string_view viseme_name(int viseme);          // 0..14: "none", "PP", ...
std::string_view expression_name(int expression);  // 0..6: "neutral", "joy", ...

}  // namespace fapc

#include "bml/face_lowering.hpp"

#include <charconv>

#include "fapc/bml/codes.hpp"
#include "fapc/codec/fap_table.hpp"
#include "fapc/vocabulary/fap_side.hpp"
#include "fapc/vocabulary/mapping_table.hpp"

namespace fapc::bml {
namespace {

struct LexemeRow {
  std::string lexeme;
  int au = 0;
  char side = 'B';
  double weight = 1;
};

// The bundled table, read once. It is fapc's own file, checked by tests/bml/bml_vocabulary_test.cpp
// (every row well formed, every unit in au_faps.tsv), so a malformed row here is a build defect and
// is skipped rather than reported to users.
const std::vector<LexemeRow>& lexeme_rows() {
  static const std::vector<LexemeRow> rows = [] {
    std::vector<LexemeRow> out;
    for (const std::vector<std::string_view>& cells : vocabulary::bundled_table_cells("bml_lexemes.tsv")) {
      if (cells.size() != 5 || cells[2].size() != 1) continue;
      LexemeRow row;
      row.lexeme = std::string(cells[0]);
      std::from_chars(cells[1].data(), cells[1].data() + cells[1].size(), row.au);
      row.side = cells[2][0];
      std::from_chars(cells[3].data(), cells[3].data() + cells[3].size(), row.weight);
      out.push_back(std::move(row));
    }
    return out;
  }();
  return rows;
}

bool on_side(int fap, char side) {
  if (side == 'B') return true;
  const vocabulary::Side s = vocabulary::fap_side(fap);
  return s == vocabulary::Side::middle || (side == 'L' ? s == vocabulary::Side::left : s == vocabulary::Side::right);
}

}  // namespace

std::map<int, double> unit_faps(int au, char side, double weight, std::vector<int>& lost) {
  std::map<int, double> out;
  const vocabulary::MappingTable& table = vocabulary::action_unit_table();
  const std::string key = std::to_string(au);
  if (table.is_lost(key) || !table.has_key(key)) {
    lost.push_back(au);
    return out;
  }
  for (const vocabulary::MappingRow& row : table.rows_of(key))
    if (row.fap != 0 && on_side(row.fap, side)) out[row.fap] += row.amount * weight;
  return out;
}

std::map<int, double> lexeme_faps(const std::string& lexeme, std::vector<int>& lost) {
  std::map<int, double> out;
  for (const LexemeRow& row : lexeme_rows()) {
    if (row.lexeme != lexeme) continue;
    for (const auto& [fap, value] : unit_faps(row.au, row.side, row.weight, lost)) out[fap] += value;
  }
  return out;
}

std::vector<std::string> standard_lexemes() {
  std::vector<std::string> out;
  for (const LexemeRow& row : lexeme_rows())
    if (out.empty() || out.back() != row.lexeme) out.push_back(row.lexeme);
  return out;
}

std::vector<KeyPoint> envelope(const std::array<double, kStandardPoints>& t, double peak, bool shift) {
  const double s = t[kStart];
  if (shift) return {{0, 0, Interpolation::sin}, {t[kEnd] - s, peak, Interpolation::linear}};
  return {{0, 0, Interpolation::sin},
          {t[kReady] - s, peak, Interpolation::linear},
          {t[kRelax] - s, peak, Interpolation::sin},
          {t[kEnd] - s, 0, Interpolation::linear}};
}

void lower_face(const Behaviour& b, const std::array<double, kStandardPoints>& t, double origin, Timeline& out,
                Diagnostics& warnings) {
  std::vector<int> lost;
  const std::map<int, double> faps =
      b.kind == BehaviourKind::face_facs ? unit_faps(b.au, b.side, 1.0, lost) : lexeme_faps(b.lexeme, lost);
  for (int au : lost)
    warnings.push_back(
        make_warning(codes::bml::unit_not_drawn, b.where,
                     "action unit " + std::to_string(au) + " moves no FAP (fapc's au_faps.tsv): not drawn"));
  if (faps.empty() && lost.empty()) {
    warnings.push_back(
        make_warning(codes::bml::unknown_lexeme, b.where,
                     "face lexeme '" + b.lexeme +
                         "' is not in fapc's vocabulary (the 17 of BML 1.0, docs/bml.md): its timing is kept"));
    return;
  }
  for (const auto& [fap, value] : faps) {
    Clip clip;
    clip.target = std::string(find_fap(fap)->name);
    clip.begin = origin + t[kStart];
    clip.end = origin + t[kEnd];
    clip.curve.keys = envelope(t, value * b.amount, b.shift);
    clip.blend = BlendMode::add;
    clip.fill = b.shift ? Fill::freeze : Fill::remove;
    clip.source = b.where;
    out.clips.push_back(std::move(clip));
  }
}

}  // namespace fapc::bml

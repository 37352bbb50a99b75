#include "bml/face_lowering.hpp"

#include <algorithm>
#include <charconv>
#include <unordered_map>

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

// A face's FAPs at amount 1 (ascending, as lexeme_faps and unit_faps give them, each with its
// target) and the units no FAP carries.
struct FaceFaps {
  std::vector<std::pair<int, double>> faps;
  std::vector<TargetName> targets;
  std::vector<int> lost;
};

FaceFaps face_faps(const std::map<int, double>& faps, std::vector<int> lost) {
  FaceFaps out;
  out.lost = std::move(lost);
  for (const auto& [fap, value] : faps) {
    out.faps.emplace_back(fap, value);
    out.targets.emplace_back(find_fap(fap)->name);
  }
  return out;
}

// Every lexeme of the table and every unit on each side, worked out once: a document names the
// same few faces thousands of times, and each working out walks the tables and builds maps.
const FaceFaps* known_lexeme(const std::string& lexeme) {
  static const std::unordered_map<std::string, FaceFaps> table = [] {
    std::unordered_map<std::string, FaceFaps> out;
    for (const std::string& name : standard_lexemes()) {
      std::vector<int> lost;
      std::map<int, double> faps = lexeme_faps(name, lost);
      out.emplace(name, face_faps(faps, std::move(lost)));
    }
    return out;
  }();
  const auto found = table.find(lexeme);
  return found == table.end() ? nullptr : &found->second;
}

constexpr int kMaxUnit = 99;  // faceFacs' au, as the reader checks it
constexpr std::string_view kSides = "BLR";

// nullptr for a unit or side outside the table (a user's lexicon may name one).
const FaceFaps* known_unit(int au, char side) {
  static const std::vector<FaceFaps> table = [] {
    std::vector<FaceFaps> out;
    for (int unit = 0; unit <= kMaxUnit; ++unit)
      for (const char s : kSides) {
        std::vector<int> lost;
        std::map<int, double> faps = unit_faps(unit, s, 1.0, lost);
        out.push_back(face_faps(faps, std::move(lost)));
      }
    return out;
  }();
  const std::size_t s = kSides.find(side);
  if (au < 0 || au > kMaxUnit || s == std::string_view::npos) return nullptr;
  return &table[static_cast<std::size_t>(au) * kSides.size() + s];
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

std::size_t face_clip_count(const Behaviour& b) {
  const FaceFaps* known = b.kind == BehaviourKind::face_facs ? known_unit(b.au, b.side) : known_lexeme(b.lexeme);
  return known != nullptr ? known->faps.size() : 0;
}

void lower_face(const Behaviour& b, const std::array<double, kStandardPoints>& t, double origin, Timeline& out,
                Diagnostics& warnings) {
  const FaceFaps* known = b.kind == BehaviourKind::face_facs ? known_unit(b.au, b.side) : known_lexeme(b.lexeme);
  FaceFaps worked_out;  // what no table holds: an unknown lexeme (nothing), a unit outside the table
  if (known == nullptr && b.kind == BehaviourKind::face_facs) {
    std::vector<int> lost;
    const std::map<int, double> faps = unit_faps(b.au, b.side, 1.0, lost);
    worked_out = face_faps(faps, std::move(lost));
  }
  const FaceFaps& face = known != nullptr ? *known : worked_out;
  for (int au : face.lost)
    warnings.push_back(
        make_warning(codes::bml::unit_not_drawn, b.where,
                     "action unit " + std::to_string(au) + " moves no FAP (fapc's au_faps.tsv): not drawn"));
  if (face.faps.empty() && face.lost.empty()) {
    warnings.push_back(
        make_warning(codes::bml::unknown_lexeme, b.where,
                     "face lexeme '" + b.lexeme +
                         "' is not in fapc's vocabulary (the 17 of BML 1.0, docs/bml.md): its timing is kept"));
    return;
  }
  for (std::size_t i = 0; i < face.faps.size(); ++i) {
    const double value = face.faps[i].second;
    Clip clip;
    clip.target = face.targets[i];
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

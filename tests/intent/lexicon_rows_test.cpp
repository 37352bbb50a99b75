// Each row of fapc's behaviour lexicon (data/intentions.tsv) shows in the frames during its span:
// an FML-APML intention of the row's type and value, on a span of 1 s to 3 s, is compiled with a
// lexicon holding that row alone (--lexicon: it replaces fapc's rows of that intention and value),
// and the FAP the row should move is read at the
// row's peak. Which FAP, and which way, is worked out here from the vocabulary tables
// independently of the lowering: the unit's (or the lexeme's units') largest FAP and its sign,
// the head rotation a head lexeme names, the eye or head rotation of a direction.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "fapc/codec/fap_table.hpp"
#include "fapc/vocabulary/behaviour_lexicon.hpp"
#include "fapc/vocabulary/fap_side.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "intent_test_support.hpp"

namespace fapc {
namespace {

using vocabulary::LexiconBehaviour;
using vocabulary::LexiconRow;

constexpr double kStart = 1.0;
constexpr double kEnd = 3.0;

int fap_named(const char* name) { return find_fap(std::string_view(name))->number; }

bool on_side(int fap, char side) {
  if (side == 'B') return true;
  const vocabulary::Side s = vocabulary::fap_side(fap);
  return s == vocabulary::Side::middle || (side == 'L') == (s == vocabulary::Side::left);
}

// FAP -> value at full amount of a unit on a side, from au_faps.tsv.
void add_unit(std::map<int, double>& out, int unit, char side, double weight) {
  for (const vocabulary::MappingRow& row : vocabulary::action_unit_table().rows_of(std::to_string(unit)))
    if (row.fap != 0 && on_side(row.fap, side)) out[row.fap] += row.amount * weight;
}

// A lexeme's units from bml_lexemes.tsv (lexeme, au, side, weight, reason), read here.
void add_lexeme(std::map<int, double>& out, const std::string& lexeme) {
  std::istringstream lines{std::string(vocabulary::bundled_table_text("bml_lexemes.tsv"))};
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream cells(line);
    std::string name, au, side, weight;
    std::getline(cells, name, '\t');
    std::getline(cells, au, '\t');
    std::getline(cells, side, '\t');
    std::getline(cells, weight, '\t');
    if (name == lexeme) add_unit(out, std::stoi(au), side[0], std::stod(weight));
  }
}

// The FAP the row must move and the sign of its motion.
std::pair<int, int> expected_motion(const LexiconRow& row) {
  std::map<int, double> faps;
  const bool left = row.name.find("LEFT") != std::string::npos;
  const bool right = row.name.find("RIGHT") != std::string::npos;
  const bool up = row.name.find("UP") != std::string::npos;
  switch (row.behaviour) {
    case LexiconBehaviour::unit:
      add_unit(faps, row.unit, row.side, 1);
      break;
    case LexiconBehaviour::lexeme:
      add_lexeme(faps, row.name);
      break;
    case LexiconBehaviour::head:
      if (row.name == "NOD") return {fap_named("head_pitch"), 1};  // pitch down is positive
      if (row.name == "SHAKE") return {fap_named("head_yaw"), 1};
      return {fap_named("head_roll"), row.name == "TILT_LEFT" ? -1 : 1};
    case LexiconBehaviour::gaze:
      if (left || right) return {fap_named("yaw_l_eyeball"), left ? 1 : -1};
      return {fap_named("pitch_l_eyeball"), up ? -1 : 1};
    case LexiconBehaviour::head_turn:
      if (left || right) return {fap_named("head_yaw"), left ? 1 : -1};
      return {fap_named("head_pitch"), up ? -1 : 1};
    case LexiconBehaviour::none:
      return {0, 0};
  }
  int best = 0;
  for (const auto& [fap, value] : faps)
    if (best == 0 || std::abs(value) > std::abs(faps[best])) best = fap;
  return {best, faps[best] > 0 ? 1 : -1};
}

std::string row_text(const LexiconRow& row) {
  std::istringstream lines{std::string(vocabulary::bundled_table_text("intentions.tsv"))};
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n)
    if (n == row.line) break;
  return line;
}

class LexiconRowShows : public testing::TestWithParam<std::size_t> {};

TEST_P(LexiconRowShows, InTheFramesDuringItsSpan) {
  const LexiconRow& row = vocabulary::bundled_behaviour_lexicon().rows[GetParam()];
  SCOPED_TRACE("intentions.tsv line " + std::to_string(row.line) + ": " + row.intention + " " + row.value + " " +
               row.name);
  const std::string tag = "row" + std::to_string(row.line);
  const std::string lexicon =
      test::write_temp(tag + ".tsv", "intention\tvalue\tbehaviour\tname\tamount\tstart\tready\trelax\tend\treason\n" +
                                         row_text(row) + "\n");
  const std::string value = row.value == "*" ? "anyvalue" : row.value;
  const std::string doc = test::write_temp(tag + ".xml", "<fml-apml><fml><" + row.intention + " id=\"i\" type=\"" +
                                                             value + "\" start=\"1\" end=\"3\"/></fml></fml-apml>\n");
  Result<pipeline::Loaded> loaded = test::load_at_25(doc, lexicon);
  ASSERT_TRUE(loaded) << loaded.error().message;
  const auto [fap, sign] = expected_motion(row);
  if (fap == 0) {  // drawn as nothing on purpose: no FAP moves, and the span is kept
    for (const FapFrame& f : loaded->frames.frames)
      for (int p = 1; p <= kFapCount; ++p) EXPECT_FALSE(f.has(p) && f.value(p) != 0) << "FAP " << p;
    EXPECT_GE(loaded->frames.frames.size(), static_cast<std::size_t>(kEnd * 25));
    return;
  }
  const double peak = kStart + row.ready * (kEnd - kStart);
  const double at_peak = test::fap_at(loaded->frames, fap, peak);
  EXPECT_GT(sign * at_peak, 0) << "FAP " << fap << " at " << peak << " s is " << at_peak;
  EXPECT_EQ(test::fap_at(loaded->frames, fap, kStart - 0.1), 0) << "moves before its span";
  EXPECT_EQ(test::fap_at(loaded->frames, fap, kEnd + 0.1), 0) << "moves after its span";
}

INSTANTIATE_TEST_SUITE_P(EveryRow, LexiconRowShows,
                         testing::Range<std::size_t>(0, vocabulary::bundled_behaviour_lexicon().rows.size()),
                         [](const testing::TestParamInfo<std::size_t>& p) {
                           const LexiconRow& row = vocabulary::bundled_behaviour_lexicon().rows[p.param];
                           return "line" + std::to_string(row.line);
                         });

}  // namespace
}  // namespace fapc

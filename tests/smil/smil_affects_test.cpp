// smil_affects.tsv, row by row: every row is well formed and names a behaviour the vocabulary
// draws, and every row's behaviour shows in the rendered frames during its affect's span (and
// not before or after it). The expected FAP values are the vocabulary's own (bml_lexemes.tsv,
// au_faps.tsv) summed here over the affect's rows, independently of the reader's placing.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "bml/face_lowering.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "smil/agent_behaviours.hpp"
#include "support/test_support.hpp"

namespace fapc::smil {
namespace {

namespace fs = std::filesystem;

// The FAPs of one row at amount 1 (the reader scales by the row's amount and the intensity).
std::map<int, double> row_faps(const AffectRow& row) {
  std::vector<int> lost;
  if (row.behaviour.starts_with("AU")) {
    int au = 0;
    std::from_chars(row.behaviour.data() + 2, row.behaviour.data() + row.behaviour.size(), au);
    return bml::unit_faps(au, 'B', 1.0, lost);
  }
  return bml::lexeme_faps(row.behaviour, lost);
}

TEST(SmilAffects, EveryRowIsWellFormedAndDrawable) {
  // No row is skipped by the reader's parser: every row has its four cells.
  const auto cells = vocabulary::bundled_table_cells("smil_affects.tsv");
  ASSERT_EQ(affect_rows().size(), cells.size());
  for (const auto& row : cells) EXPECT_EQ(row.size(), 4u) << row[0];
  const std::vector<std::string> lexemes = bml::standard_lexemes();
  for (const AffectRow& row : affect_rows()) {
    SCOPED_TRACE(row.affect + " " + row.behaviour);
    EXPECT_GT(row.amount, 0);
    EXPECT_LE(row.amount, 1);
    EXPECT_GT(row.reason.size(), 20u) << "each row says why it holds";
    if (!row.behaviour.starts_with("AU")) {
      EXPECT_NE(std::find(lexemes.begin(), lexemes.end(), row.behaviour), lexemes.end()) << "not a BML lexeme";
    }
    EXPECT_FALSE(row_faps(row).empty()) << "draws no FAP";
  }
  for (const char* affect : {"SmileOpen", "SmileClosed", "Sad", "Anger", "Fear", "Disgust", "Surprise", "sorry-for"}) {
    EXPECT_FALSE(affect_behaviours(affect, 1, false, {}).empty()) << affect;
  }
}

// The frames of a script with the affect alone from 1 s to 3 s at intensity 0.8.
FapSequence frames_of(const std::string& affect) {
  const fs::path dir = test::scratch_folder("smil-affect");
  const fs::path path = dir / "affect.smil";
  std::ofstream(path) << "<par><speech-animation affect=\"" << affect
                      << "\" intensity=\"0.8\" begin=\"1s\" dur=\"2s\"/><par dur=\"4s\"/></par>\n";
  pipeline::ConvertOptions options;
  options.fps = 25;
  Result<pipeline::Loaded> loaded = pipeline::load(path.string(), options);
  EXPECT_TRUE(loaded) << (loaded ? "" : loaded.error().message);
  return loaded ? loaded->frames : FapSequence{};
}

double value_at(const FapSequence& frames, std::size_t frame, int fap) {
  if (frame >= frames.frames.size()) return NAN;
  const FapFrame& f = frames.frames[frame];
  return f.has(fap) ? f.value(fap) : 0.0;
}

class SmilAffectRow : public ::testing::TestWithParam<std::size_t> {};

TEST_P(SmilAffectRow, ShowsInTheFramesDuringItsSpan) {
  const AffectRow& row = affect_rows()[GetParam()];
  SCOPED_TRACE(row.affect + " " + row.behaviour);
  // What the affect's rows draw together at the hold.
  std::map<int, double> total;
  for (const AffectRow& other : affect_rows())
    if (other.affect == row.affect)
      for (const auto& [fap, value] : row_faps(other)) total[fap] += value * other.amount * 0.8;
  const FapSequence frames = frames_of(row.affect);
  ASSERT_GE(frames.frames.size(), 100u);
  int shown = 0;
  for (const auto& [fap, value] : row_faps(row)) {
    EXPECT_EQ(value_at(frames, 12, fap), 0) << "FAP " << fap << " moves before the span (0.5 s)";
    EXPECT_EQ(value_at(frames, 90, fap), 0) << "FAP " << fap << " still moves after the span (3.6 s)";
    const double held = value_at(frames, 50, fap);  // 2 s: between the onset's end and the offset
    EXPECT_NEAR(held, std::round(total[fap]), 1.0) << "FAP " << fap;
    // The row's own contribution is visible: moved its way, by at least half of it.
    const double own = value * row.amount * 0.8;
    if (std::abs(own) >= 2 && held * own > 0 && std::abs(held) >= std::abs(own) / 2) ++shown;
  }
  EXPECT_GT(shown, 0) << "no FAP of this row moves its way during the span";
}

INSTANTIATE_TEST_SUITE_P(Rows, SmilAffectRow, ::testing::Range<std::size_t>(0, affect_rows().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& param) {
                           const AffectRow& row = affect_rows()[param.param];
                           std::string name = std::to_string(param.param) + "_" + row.affect + "_" + row.behaviour;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace fapc::smil

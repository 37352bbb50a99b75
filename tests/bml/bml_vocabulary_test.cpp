// The bundled lexeme table (transcoder/vocabulary/data/bml_lexemes.tsv) is read by a lenient
// reader (a malformed row of fapc's own file would be skipped): this test holds the file to its
// form instead. Every row has five cells, a known side, a weight in (0, 1], a reason, and a unit
// that au_faps.tsv maps; the table names BML 1.0's 17 lexemes.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "bml/face_lowering.hpp"
#include "fapc/vocabulary/mapping_table.hpp"

namespace fapc::bml {
namespace {

TEST(BmlVocabulary, EveryRowIsWellFormedAndItsUnitIsMapped) {
  std::istringstream text{std::string(vocabulary::bundled_table_text("bml_lexemes.tsv"))};
  std::string line;
  bool header = true;
  int rows = 0;
  while (std::getline(text, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      EXPECT_EQ(line, "lexeme\tau\tside\tweight\treason");
      header = false;
      continue;
    }
    std::vector<std::string> cells;
    std::istringstream split(line);
    for (std::string cell; std::getline(split, cell, '\t');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 5u) << line;
    EXPECT_TRUE(cells[2] == "B" || cells[2] == "L" || cells[2] == "R") << line;
    const double weight = std::stod(cells[3]);
    EXPECT_GT(weight, 0) << line;
    EXPECT_LE(weight, 1) << line;
    EXPECT_GT(cells[4].size(), 20u) << "a reason: " << line;
    EXPECT_TRUE(vocabulary::action_unit_table().has_key(cells[1])) << line;
    EXPECT_FALSE(vocabulary::action_unit_table().is_lost(cells[1])) << line;
    ++rows;
  }
  EXPECT_GT(rows, 17);
}

TEST(BmlVocabulary, TheSeventeenLexemesOfBml10) {
  const std::vector<std::string> expected = {"OBLIQUE_BROWS",
                                             "RAISE_BROWS",
                                             "RAISE_LEFT_BROW",
                                             "RAISE_RIGHT_BROW",
                                             "LOWER_BROWS",
                                             "LOWER_LEFT_BROW",
                                             "LOWER_RIGHT_BROW",
                                             "LOWER_MOUTH_CORNERS",
                                             "LOWER_LEFT_MOUTH_CORNER",
                                             "LOWER_RIGHT_MOUTH_CORNER",
                                             "RAISE_MOUTH_CORNERS",
                                             "RAISE_LEFT_MOUTH_CORNER",
                                             "RAISE_RIGHT_MOUTH_CORNER",
                                             "OPEN_MOUTH",
                                             "OPEN_LIPS",
                                             "WIDEN_EYES",
                                             "CLOSE_EYES"};
  EXPECT_EQ(standard_lexemes(), expected);
  for (const std::string& lexeme : expected) {
    std::vector<int> lost;
    EXPECT_FALSE(lexeme_faps(lexeme, lost).empty()) << lexeme;
    EXPECT_TRUE(lost.empty()) << lexeme;
  }
}

}  // namespace
}  // namespace fapc::bml

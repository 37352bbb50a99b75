// The behaviour lexicon's parser (fapc/vocabulary/behaviour_lexicon.hpp): fapc's own table reads
// whole, a user's file is refused at the cell that is wrong, and lookups fall back as documented.
#include <gtest/gtest.h>

#include "fapc/vocabulary/behaviour_lexicon.hpp"
#include "fapc/vocabulary/mapping_table.hpp"

namespace fapc::vocabulary {
namespace {

constexpr const char* kHeader = "intention\tvalue\tbehaviour\tname\tamount\tstart\tready\trelax\tend\treason\n";

Result<BehaviourLexicon> parse(const std::string& rows) { return parse_behaviour_lexicon(kHeader + rows, "my.tsv"); }

TEST(BehaviourLexicon, TheBundledTableReadsWhole) {
  const BehaviourLexicon& lexicon = bundled_behaviour_lexicon();
  // Every line of data/intentions.tsv that is not a comment or the header is a row.
  const std::string_view text = bundled_table_text("intentions.tsv");
  std::size_t lines = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    if (end > at && text[at] != '#') ++lines;
    at = end + 1;
  }
  EXPECT_EQ(lexicon.rows.size() + 1, lines);
  EXPECT_GT(lexicon.rows.size(), 50u);
  for (const char* intention : {"emotion", "performative", "emphasis", "deictic", "certainty", "turntaking",
                                "backchannel", "belief-relation", "boundary", "theme", "rheme"})
    EXPECT_TRUE(lexicon.knows(intention)) << intention;
}

TEST(BehaviourLexicon, ValuesMatchWithoutCaseThenStarThenAffectAsEmotion) {
  const auto lexicon = parse(
      "emotion\tjoy\tau\t12\t1\t0\t0.2\t0.8\t1\tsmile\n"
      "emphasis\t*\tlexeme\tRAISE_BROWS\t0.5\t0\t0.2\t0.8\t1\tbrows\n");
  ASSERT_TRUE(lexicon) << lexicon.error().message;
  EXPECT_EQ(lexicon->rows_for("emotion", "JOY").size(), 1u);
  EXPECT_EQ(lexicon->rows_for("emphasis", "Hstar").size(), 1u);
  EXPECT_EQ(lexicon->rows_for("affect", "joy").size(), 1u);
  EXPECT_TRUE(lexicon->rows_for("emotion", "anger").empty());
  EXPECT_TRUE(lexicon->knows("affect"));
  EXPECT_FALSE(lexicon->knows("deictic"));
  EXPECT_EQ(lexicon->rows[0].unit, 12);
}

TEST(BehaviourLexicon, AUserLexiconExtendsFapcsOwnAndReplacesWhatItNames) {
  auto mine = parse(
      "emotion\tjoy\tlexeme\tRAISE_MOUTH_CORNERS\t1\t0\t0.2\t0.8\t1\ta plain smile\n"
      "wink\t*\tau\tL46\t1\t0\t0.2\t0.8\t1\tone eye\n");
  ASSERT_TRUE(mine) << mine.error().message;
  mine->base = &bundled_behaviour_lexicon();
  ASSERT_EQ(mine->rows_for("emotion", "joy").size(), 1u);
  EXPECT_EQ(mine->rows_for("emotion", "joy")[0]->name, "RAISE_MOUTH_CORNERS");
  EXPECT_EQ(mine->rows_for("wink", "left").size(), 1u);
  EXPECT_EQ(mine->rows_for("emotion", "anger"), bundled_behaviour_lexicon().rows_for("emotion", "anger"));
  EXPECT_FALSE(mine->rows_for("emotion", "anger").empty());
  EXPECT_TRUE(mine->knows("performative"));
}

TEST(BehaviourLexicon, OneSidedUnitsAndRepeatedHeadLexemes) {
  const auto lexicon = parse(
      "a\tb\tau\tL12\t1\t0\t0.2\t0.8\t1\tleft corner\n"
      "a\tb\thead\tNOD*3\t1\t0\t0.2\t0.8\t1\tthree nods\n");
  ASSERT_TRUE(lexicon) << lexicon.error().message;
  EXPECT_EQ(lexicon->rows[0].side, 'L');
  EXPECT_EQ(lexicon->rows[1].name, "NOD");
  EXPECT_EQ(lexicon->rows[1].repetition, 3);
}

struct BadRow {
  const char* row;
  int column;
  const char* says;
};

TEST(BehaviourLexicon, BadRowsAreRefusedAtTheirCell) {
  const BadRow cases[] = {
      {"a\tb\tsmile\tX\t1\t0\t0.2\t0.8\t1\tr\n", 5, "not a behaviour"},
      {"a\tb\tlexeme\tSMILE\t1\t0\t0.2\t0.8\t1\tr\n", 12, "not a face lexeme"},
      {"a\tb\tau\t57\t1\t0\t0.2\t0.8\t1\tr\n", 8, "moves no FAP"},
      {"a\tb\tau\t120\t1\t0\t0.2\t0.8\t1\tr\n", 8, "not an action unit"},
      {"a\tb\thead\tWOBBLE\t1\t0\t0.2\t0.8\t1\tr\n", 10, "not a head lexeme"},
      {"a\tb\thead\tNOD*0\t1\t0\t0.2\t0.8\t1\tr\n", 10, "repetitions"},
      {"a\tb\tgaze\tBEHIND\t10\t0\t0.2\t0.8\t1\tr\n", 10, "not a direction"},
      {"a\tb\tgaze\tLEFT\t90\t0\t0.2\t0.8\t1\tr\n", 15, "60 degrees"},
      {"a\tb\tnone\tX\t0\t0\t0\t1\t1\tr\n", 10, "write '-'"},
      {"a\tb\tau\t12\tlots\t0\t0.2\t0.8\t1\tr\n", 11, "not a number"},
      {"a\tb\tau\t12\t1\t0\t1.2\t0.8\t1\tr\n", 15, "not a fraction"},
      {"a\tb\tau\t12\t1\t0\t0.5\t0.4\t1\tr\n", 19, "must not decrease"},
      {"a\tb\tau\t12\t1\t0.5\t0.5\t0.5\t0.5\tr\n", 25, "end after it starts"},
      {"a\tb\tau\t12\t1\t0\t0.2\t0.8\t1\t\n", 25, "reason is empty"},
      {"a\t\tau\t12\t1\t0\t0.2\t0.8\t1\tr\n", 3, "value is empty"},
  };
  for (const BadRow& c : cases) {
    SCOPED_TRACE(c.row);
    const auto lexicon = parse(c.row);
    ASSERT_FALSE(lexicon);
    EXPECT_EQ(lexicon.error().where.file, "my.tsv");
    EXPECT_EQ(lexicon.error().where.line, 2);
    EXPECT_EQ(lexicon.error().where.column, c.column);
    EXPECT_NE(lexicon.error().message.find(c.says), std::string::npos) << lexicon.error().message;
  }
}

TEST(BehaviourLexicon, AWrongHeaderIsNamed) {
  const auto lexicon = parse_behaviour_lexicon("intention\tvalue\tface\n", "h.tsv");
  ASSERT_FALSE(lexicon);
  EXPECT_EQ(lexicon.error().where.column, 17);
  EXPECT_NE(lexicon.error().message.find("'behaviour'"), std::string::npos);
}

TEST(BehaviourLexicon, TooManyRowsAreRefusedBeforeTheyAreStored) {
  std::string rows;
  for (std::size_t i = 0; i <= kMaxLexiconRows; ++i) rows += "a\tb\tau\t12\t1\t0\t0.2\t0.8\t1\tr\n";
  const auto lexicon = parse(rows);
  ASSERT_FALSE(lexicon);
  EXPECT_EQ(lexicon.error().kind, ErrorKind::limit_exceeded);
}

}  // namespace
}  // namespace fapc::vocabulary

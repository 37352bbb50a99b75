// A user's table is read by the same parser as the bundled ones: every refusal points at the line
// and column of what it refuses.
#include <gtest/gtest.h>

#include <string>

#include "fapc/vocabulary/mapping_table.hpp"
#include "fapc/vocabulary/visemes.hpp"

namespace fapc::vocabulary {
namespace {

const std::string kHeader = "# a comment\nau\tfap\tdirection\tamount\treason\n";

struct Expected {
  int line;
  int column;
  const char* words;  // a part of the message naming the fault
};

void expect_error(const std::string& text, TableKind kind, Expected expected) {
  Result<MappingTable> parsed = parse_mapping_table(text, "t.tsv", kind);
  ASSERT_FALSE(parsed.ok()) << text;
  EXPECT_EQ(parsed.error().where.line, expected.line) << parsed.error().message;
  EXPECT_EQ(parsed.error().where.column, expected.column) << parsed.error().message;
  EXPECT_NE(parsed.error().message.find(expected.words), std::string::npos) << parsed.error().message;
}

TEST(VocabularyParse, AGoodTableReadsItsRows) {
  Result<MappingTable> parsed = parse_mapping_table(
      kHeader + "12\traise_l_cornerlip\tup\t260\tsmile\n12\t13\tup\t260\tthe other side\r\n57\t-\t-\t0\tlost\n",
      "t.tsv", TableKind::action_units);
  ASSERT_TRUE(parsed.ok()) << format_diagnostic(parsed.error());
  ASSERT_EQ(parsed->rows.size(), 3u);
  EXPECT_EQ(parsed->rows[1].fap, 13);  // a FAP by number reads too
  EXPECT_EQ(parsed->rows[1].line, 4);
  EXPECT_EQ(parsed->rows[0].amount, 260);
  EXPECT_TRUE(parsed->is_lost("57"));
  EXPECT_FALSE(parsed->is_lost("12"));
}

TEST(VocabularyParse, PositionedErrors) {
  const TableKind au = TableKind::action_units;
  expect_error(kHeader + "12\traise_l_corner\tup\t260\tr\n", au, {3, 4, "did you mean"});
  expect_error(kHeader + "12\traise_l_cornerlip\tdown\t260\tr\n", au, {3, 22, "moves up"});
  expect_error(kHeader + "12\traise_l_cornerlip\tup\tlots\tr\n", au, {3, 25, "not a non-zero number"});
  expect_error(kHeader + "12\traise_l_cornerlip\tup\t5000\tr\n", au, {3, 25, "legal range"});
  expect_error(kHeader + "12\traise_l_cornerlip\tup\t260\t\n", au, {3, 29, "reason is empty"});
  expect_error(kHeader + "100\topen_jaw\tdown\t1\tr\n", au, {3, 1, "action unit number"});
  expect_error(kHeader + "12\topen_jaw\tdown\t1\tr\n12\topen_jaw\tdown\t2\tr\n", au, {4, 4, "already given on line 3"});
  expect_error(kHeader + "57\t-\t-\t0\tr\n57\topen_jaw\tdown\t2\tr\n", au, {4, 4, "both"});
  expect_error(kHeader + "57\t-\tup\t0\tr\n", au, {3, 6, "'-'"});
  expect_error(kHeader + "12\topen_jaw\tdown\t1\n", au, {3, 19, "4 tab-separated cells"});
  expect_error(kHeader + "12\topen_jaw\tdown\t1\tr\textra\n", au, {3, 22, "more than 5"});
  expect_error(kHeader + "12\tviseme\tdown\t1\tr\n", au, {3, 4, "high-level"});
  expect_error("au\tfap\tway\tamount\treason\n", au, {1, 8, "expected 'direction'"});
  expect_error("# only comments\n", au, {1, 1, "no header"});
  expect_error("shape\tfap\tdirection\tamount\treason\neyeBlinkLeftt\t19\tdown\t1\tr\n", TableKind::arkit_shapes,
               {2, 1, "did you mean eyeBlinkLeft"});
  expect_error("shape\tfap\tdirection\tamount\treason\neyeBlinkLeft\t19\tdown\t1\tr\n", TableKind::arkit_shapes,
               {1, 1, "has no row"});
}

TEST(VocabularyParse, RowsBeyondTheLimitAreRefusedBeforeTheyAreStored) {
  std::string text = kHeader;
  for (std::size_t i = 0; i <= kMaxTableRows; ++i) text += "3\topen_jaw\tdown\t1\tr\n";
  Result<MappingTable> parsed = parse_mapping_table(text, "t.tsv", TableKind::action_units);
  ASSERT_FALSE(parsed.ok());
  EXPECT_EQ(parsed.error().kind, ErrorKind::limit_exceeded);
}

TEST(VocabularyParse, VisemeTableErrors) {
  const std::string header = "viseme\tmpeg4\topenxr\treason\n";
  Result<std::vector<VisemeRow>> bad_name = parse_viseme_table(header + "1\tpp\tPP\tr\n", "v.tsv");
  ASSERT_FALSE(bad_name.ok());
  EXPECT_EQ(bad_name.error().where.line, 2);
  EXPECT_EQ(bad_name.error().where.column, 3);
  Result<std::vector<VisemeRow>> missing = parse_viseme_table(header + "0\tnone\tsil\tr\n", "v.tsv");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("viseme 1 (PP) has no row"), std::string::npos);
  Result<std::vector<VisemeRow>> twice = parse_viseme_table(header + "0\tnone\tsil\tr\n1\tPP\tsil\tr\n", "v.tsv");
  ASSERT_FALSE(twice.ok());
  EXPECT_EQ(twice.error().where.column, 6);
}

}  // namespace
}  // namespace fapc::vocabulary

// The caret under a diagnostic (docs/cli.md, its Diagnostics rule): a short line is shown whole; a long
// one as a window of at most 100 characters around the column, "..." on each cut side, the caret
// under the character the column names, UTF-8 characters never cut. The expectations of the long
// lines are checked by reading the rendered text back (which character stands above the caret),
// not by a second copy of the windowing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fapc/codec/codes.hpp"
#include "fapc/codec/diagnostic.hpp"

namespace fapc {
namespace {

Diagnostic at_column(std::string line, int column) {
  return make_error(codes::fap::not_a_number, Location::text("in.mimic", 1, column), "unexpected character",
                    std::move(line));
}

// The rendered diagnostic's shown line and caret line.
struct Shown {
  std::string line;
  std::string caret;
};
Shown shown(const std::string& rendered) {
  const auto first = rendered.find('\n');
  const auto second = rendered.find('\n', first + 1);
  return {rendered.substr(first + 1, second - first - 1), rendered.substr(second + 1)};
}

// The UTF-8 characters of `s`, one string each (a continuation byte joins the one before it).
std::vector<std::string> characters(const std::string& s) {
  std::vector<std::string> out;
  for (char c : s) {
    if (!out.empty() && (static_cast<unsigned char>(c) & 0xC0) == 0x80) {
      out.back() += c;
    } else {
      out.emplace_back(1, c);
    }
  }
  return out;
}

// The character of the shown line above the caret: the caret line counts one column per
// character (a tab under a tab).
std::string above_caret(const Shown& s) {
  const auto chars = characters(s.line);
  const auto at = s.caret.find('^');
  return at < chars.size() ? chars[at] : "";
}

TEST(CaretWindow, AShortLineIsShownWhole) {
  EXPECT_EQ(render_with_caret(at_column("main { jaw @ }", 12)),
            "in.mimic:1:12: error: unexpected character\nmain { jaw @ }\n           ^");
  // A tab before the column stays a tab under it.
  EXPECT_EQ(render_with_caret(at_column("\tjaw @", 6)), "in.mimic:1:6: error: unexpected character\n\tjaw @\n\t    ^");
  // One past the end: the caret after the line.
  EXPECT_EQ(render_with_caret(at_column("jaw", 4)), "in.mimic:1:4: error: unexpected character\njaw\n   ^");
}

TEST(CaretWindow, AMegabyteLineShowsAWindowAroundTheColumn) {
  std::string line(1 << 20, 'a');
  const std::size_t at = 600000;
  line[at] = '@';
  const auto rendered = render_with_caret(at_column(line, static_cast<int>(at) + 1));
  EXPECT_LT(rendered.size(), 400U);
  const auto s = shown(rendered);
  EXPECT_EQ(s.line.substr(0, 3), "...");
  EXPECT_EQ(s.line.substr(s.line.size() - 3), "...");
  EXPECT_EQ(s.line.size(), 106U);  // 100 characters and two cut marks
  EXPECT_EQ(above_caret(s), "@");
}

TEST(CaretWindow, NearEitherEndOnlyTheOtherSideIsCut) {
  std::string line(5000, 'a');
  line[3] = '@';
  auto s = shown(render_with_caret(at_column(line, 4)));
  EXPECT_EQ(s.line.substr(0, 4), "aaa@");
  EXPECT_EQ(s.line.size(), 103U);
  EXPECT_EQ(above_caret(s), "@");

  line[3] = 'a';
  line[4998] = '@';
  s = shown(render_with_caret(at_column(line, 4999)));
  EXPECT_EQ(s.line.substr(s.line.size() - 2), "@a");
  EXPECT_EQ(s.line.size(), 103U);
  EXPECT_EQ(above_caret(s), "@");

  // Past the end of a long line: the last characters, the caret after them.
  s = shown(render_with_caret(at_column(line, 5001)));
  EXPECT_EQ(s.line.substr(0, 3), "...");
  EXPECT_EQ(s.caret.find('^'), s.line.size());
}

TEST(CaretWindow, MultiByteCharactersAreNeverCutAndTheCaretCountsCharacters) {
  // 3000 two-byte characters and three-byte ones alternating, one '@' among them.
  std::string line;
  for (int i = 0; i < 3000; ++i) line += i % 2 ? "\xC3\xA9" : "\xE2\x82\xAC";  // é, €
  const std::size_t at = line.size() / 2 + 1;  // inside a character: the caret goes to its start
  const auto rendered = render_with_caret(at_column(line, static_cast<int>(at) + 1));
  const auto s = shown(rendered);
  const auto chars = characters(s.line);
  ASSERT_EQ(chars.size(), 106U);
  for (std::size_t i = 3; i + 3 < chars.size(); ++i) {
    EXPECT_TRUE(chars[i] == "\xC3\xA9" || chars[i] == "\xE2\x82\xAC") << "character " << i << " cut";
  }
  // The character above the caret is the one holding byte `at` of the line.
  std::size_t start = at;
  while ((static_cast<unsigned char>(line[start]) & 0xC0) == 0x80) --start;
  std::size_t end = start + 1;
  while (end < line.size() && (static_cast<unsigned char>(line[end]) & 0xC0) == 0x80) ++end;
  EXPECT_EQ(above_caret(s), line.substr(start, end - start));
  // ...and it is the 41st shown (40 lead up to it), after the cut mark.
  EXPECT_EQ(s.caret.find('^'), 3U + 40U);
}

}  // namespace
}  // namespace fapc

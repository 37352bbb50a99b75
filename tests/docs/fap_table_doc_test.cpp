// docs/fap-table.md and fapcodec's FAP table state the same facts: every row of the page's table
// (transcribed from the sources the page names, not from the code) against fap_table(), and the
// page's groups against fap_groups(). A change to either that the other does not follow fails.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "fapc/codec/fap_table.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::stringstream in(row);
  std::string cell;
  std::getline(in, cell, '|');  // before the first bar
  while (std::getline(in, cell, '|')) {
    const auto first = cell.find_first_not_of(' ');
    const auto last = cell.find_last_not_of(' ');
    out.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  if (!out.empty() && out.back().empty()) out.pop_back();  // after the last bar
  return out;
}

std::vector<std::string> page_lines() {
  std::istringstream page(test::read_text(test::source_dir() + "/docs/fap-table.md"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(page, line);) lines.push_back(line);
  return lines;
}

// "±1080" -> 1080
int symmetric_range(const std::string& text) {
  static const std::regex kRange(R"re(^(?:±|\+-)([0-9]+)$)re");
  std::smatch m;
  if (!std::regex_match(text, m, kRange)) return -1;
  return std::stoi(m[1]);
}

TEST(FapTableDoc, EveryRowOfThePageMatchesTheCode) {
  static const std::regex kRow(R"re(^\| ([0-9]+) \| [a-z_]+ \|.*)re");
  int rows = 0;
  for (const std::string& line : page_lines()) {
    if (!std::regex_match(line, kRow)) continue;
    const auto c = cells(line);
    if (c.size() != 9) continue;  // another table (groups, fields)
    ++rows;
    const int number = std::stoi(c[0]);
    const FapInfo* fap = find_fap(number);
    ASSERT_NE(fap, nullptr) << line;
    EXPECT_EQ(fap->name, c[1]) << line;
    EXPECT_EQ(fapu_name(fap->unit), c[2]) << line;
    EXPECT_EQ(fap->bidirectional ? "B" : "U", c[3]) << line;
    EXPECT_EQ(fap->positive_motion, c[4]) << line;
    EXPECT_EQ(fap->group, std::stoi(c[5])) << line;
    EXPECT_EQ(fap->quant_step, std::stoi(c[6])) << line;
    EXPECT_EQ(fap->intra_range, symmetric_range(c[7])) << line;
    EXPECT_EQ(fap->predictive_range, symmetric_range(c[8])) << line;
  }
  EXPECT_EQ(rows, 66);  // FAPs 3 to 68
}

TEST(FapTableDoc, GroupsOfThePageMatchTheCode) {
  static const std::regex kGroupRow(R"re(^\| ([0-9]+) \| ([0-9]+)-([0-9]+) \| ([0-9]+) \|.*)re");
  int rows = 0;
  for (const std::string& line : page_lines()) {
    std::smatch m;
    if (!std::regex_match(line, m, kGroupRow)) continue;
    ++rows;
    const FapGroup& group = fap_groups().at(static_cast<std::size_t>(std::stoi(m[1]) - 1));
    EXPECT_EQ(group.first_fap, std::stoi(m[2])) << line;
    EXPECT_EQ(group.last_fap, std::stoi(m[3])) << line;
    EXPECT_EQ(group.last_fap - group.first_fap + 1, std::stoi(m[4])) << line;
  }
  EXPECT_EQ(rows, kFapGroupCount);
}

}  // namespace
}  // namespace fapc

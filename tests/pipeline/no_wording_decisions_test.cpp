// No code decides by a message's wording (docs/architecture.md): behaviour goes by ErrorKind and
// by values such as ScheduleError::problem. This scans every source of the libraries and the
// program for the shapes such a decision takes, so that one cannot come back unnoticed.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "support/test_support.hpp"

namespace fapc {
namespace {

// A message searched, compared or tested for a prefix or suffix.
const std::regex kWordingDecision(
    R"((\.|->)message\s*(\.\s*(r?find|starts_with|ends_with|compare|contains)\s*\(|[=!]=))");

std::vector<std::string> offending_lines(const std::string& file) {
  std::vector<std::string> found;
  std::istringstream in(test::read_text(file));
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (std::regex_search(line, kWordingDecision)) found.push_back(file + ":" + std::to_string(number) + ": " + line);
  }
  return found;
}

TEST(NoWordingDecisions, TheScanFindsTheShapesItLooksFor) {
  for (const std::string line : {"if (d.message.find(\"ends\") != npos)", "e.message.rfind(\"verification\", 0) == 0",
                                 "if (error->message == \"x\")", "d.message.starts_with(kAction)"})
    EXPECT_TRUE(std::regex_search(line, kWordingDecision)) << line;
  for (const std::string line :
       {"d.message = name + ' ' + d.message;", "d.message += \" (hint)\";", "return make_error(where, message);"})
    EXPECT_FALSE(std::regex_search(line, kWordingDecision)) << line;
}

TEST(NoWordingDecisions, NoLibraryOrProgramSourceDecidesByAMessage) {
  std::vector<std::string> found;
  for (const char* folder : {"fapcodec", "transcoder", "xmt", "tools"})
    for (const char* suffix : {".cpp", ".hpp"})
      for (const std::string& file : test::files_under(test::source_dir() + "/" + folder, suffix))
        for (const std::string& line : offending_lines(file)) found.push_back(line);
  std::string all;
  for (const std::string& line : found) all += line + "\n";
  EXPECT_TRUE(found.empty()) << "decisions by a message's wording (use ErrorKind or a value instead):\n" << all;
}

}  // namespace
}  // namespace fapc

// Runs the cases of tests/command/*.test (format in tests/command/README.md).
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <optional>
#include <sstream>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

struct Case {
  int line = 0;
  std::string args;
  int exit_status = 0;
  std::optional<std::string> out, err;
  std::vector<std::string> absent;
};

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

std::vector<Case> parse_cases(const std::string& text) {
  std::vector<Case> cases;
  std::istringstream in(text);
  std::string line;
  std::optional<std::string>* section = nullptr;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("$ fapc", 0) == 0) {
      cases.push_back(Case{number, line.substr(6), 0, {}, {}, {}});
      section = nullptr;
    } else if (cases.empty()) {
      continue;
    } else if (line.rfind("exit: ", 0) == 0) {
      cases.back().exit_status = std::stoi(line.substr(6));
    } else if (line == "stdout:") {
      section = &cases.back().out;
      *section = "";
    } else if (line == "stderr:") {
      section = &cases.back().err;
      *section = "";
    } else if (line.rfind("absent: ", 0) == 0) {
      cases.back().absent.push_back(line.substr(8));
      section = nullptr;
    } else if (section && !(line.empty() && in.peek() == '$')) {
      **section += line + "\n";
    }
  }
  return cases;
}

std::vector<std::string> command_test_files() {
  return test::files_under(test::source_dir() + "/tests/command", ".test");
}

// One test per file (CTest runs and reports each on its own): the file's stem, '-' as '_'.
class CommandFile : public testing::TestWithParam<std::string> {};

TEST(CommandFiles, Exist) { EXPECT_FALSE(command_test_files().empty()); }

TEST_P(CommandFile, EveryCaseBehavesAsWritten) {
  const std::string& file = GetParam();
  const fs::path tmp = fs::path(test::binary_dir()) / "command-tests" / fs::path(file).stem();
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  const std::vector<Case> cases = parse_cases(test::read_text(file));
  EXPECT_FALSE(cases.empty()) << file << " has no cases";
  for (const Case& c : cases) {
    const std::string args = replace_all(c.args, "$TMP", tmp.string());
    const test::CommandRun run = test::run_fapc(args);
    const std::string where = file + ":" + std::to_string(c.line) + ": fapc" + args;
    EXPECT_EQ(run.exit_status, c.exit_status) << where << "\n" << run.err;
    if (c.out) {
      EXPECT_EQ(run.out, replace_all(*c.out, "$TMP", tmp.string())) << where;
    }
    if (c.err) {
      EXPECT_EQ(run.err, replace_all(*c.err, "$TMP", tmp.string())) << where;
    }
    for (const std::string& path : c.absent)
      EXPECT_FALSE(fs::exists(replace_all(path, "$TMP", tmp.string()))) << where << ": " << path;
  }
}

std::string test_name(const testing::TestParamInfo<std::string>& file) {
  std::string name = fs::path(file.param).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Tests, CommandFile, testing::ValuesIn(command_test_files()), test_name);

}  // namespace
}  // namespace fapc

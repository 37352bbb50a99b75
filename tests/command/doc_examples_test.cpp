// Docs that are tested (docs/testing.md, "Doc examples"): every ```console block of README.md and
// docs/*.md is run, command by command, in a fresh folder holding links to the repository's
// corpus/ and docs/, with the built fapc first on the PATH; a command must exit 0 (or the status
// of a last "[exit N]" line), and where the block shows output under the command, its standard
// output must be exactly that.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

struct Example {
  int line = 0;  // of the command in its file
  std::string command;
  std::vector<std::string> output;  // the lines shown under it; empty: not checked
  int exit_status = 0;
};

std::vector<Example> examples_in(const std::string& text) {
  std::vector<Example> out;
  std::istringstream lines(text);
  bool inside = false;
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (!inside) {
      inside = line == "```console";
      continue;
    }
    if (line.starts_with("```")) {
      inside = false;
    } else if (line.starts_with("$ ")) {
      out.push_back({number, line.substr(2), {}, 0});
    } else if (!out.empty() && line.starts_with("[exit ") && line.ends_with("]")) {
      out.back().exit_status = std::stoi(line.substr(6));
    } else if (!out.empty()) {
      out.back().output.push_back(line);
    }
  }
  return out;
}

std::vector<std::string> documents() {
  std::vector<std::string> files = {test::source_dir() + "/README.md"};
  for (const std::string& page : test::files_under(test::source_dir() + "/docs", ".md"))
    if (fs::path(page).parent_path() == fs::path(test::source_dir()) / "docs") files.push_back(page);
  return files;
}

TEST(DocExamples, EveryConsoleBlockRunsAsShown) {
  const std::string bin = fs::path(test::fapc_program()).parent_path().string();
  std::size_t run = 0;
  for (const std::string& document : documents()) {
    const std::vector<Example> examples = examples_in(test::read_text(document));
    if (examples.empty()) continue;
    const fs::path folder = fs::path(test::binary_dir()) / "doc-examples" / fs::path(document).stem();
    fs::remove_all(folder);
    fs::create_directories(folder);
    for (const char* shared : {"corpus", "docs"})
      fs::create_directory_symlink(fs::path(test::source_dir()) / shared, folder / shared);
    for (const Example& example : examples) {
      const std::string where =
          fs::relative(document, test::source_dir()).string() + ":" + std::to_string(example.line);
      std::ofstream(folder / "example.sh") << example.command << '\n';
      const test::CommandRun result =
          test::run_shell("cd '" + folder.string() + "' && PATH='" + bin + "':\"$PATH\" sh example.sh");
      ++run;
      EXPECT_EQ(result.exit_status, example.exit_status) << where << ": $ " << example.command << "\n" << result.err;
      if (example.output.empty()) continue;
      std::string expected;
      for (const std::string& line : example.output) expected += line + "\n";
      EXPECT_EQ(result.out, expected) << where << ": $ " << example.command;
    }
    fs::remove_all(folder);
  }
  EXPECT_GE(run, 6u) << "README.md's everyday jobs are examples";
}

// The parser itself: commands, shown output and an expected exit status.
TEST(DocExamples, ConsoleBlocksAreReadAsWritten) {
  const auto examples = examples_in("```sh\n$ not this\n```\n```console\n$ a\nout 1\nout 2\n$ b\n[exit 3]\n```\n$ c\n");
  ASSERT_EQ(examples.size(), 2u);
  EXPECT_EQ(examples[0].command, "a");
  EXPECT_EQ(examples[0].output, (std::vector<std::string>{"out 1", "out 2"}));
  EXPECT_EQ(examples[1].command, "b");
  EXPECT_TRUE(examples[1].output.empty());
  EXPECT_EQ(examples[1].exit_status, 3);
  EXPECT_EQ(examples[0].line, 5);
}

}  // namespace
}  // namespace fapc

#include "support/test_support.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fapc::test {

namespace fs = std::filesystem;

std::string source_dir() { return FAPC_SOURCE_DIR; }
std::string binary_dir() { return FAPC_BINARY_DIR; }
std::string corpus_dir() { return source_dir() + "/corpus"; }
std::string fapc_program() { return binary_dir() + "/bin/fapc"; }

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ADD_FAILURE() << "cannot read " << path;
    return {};
  }
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<std::string> files_under(const std::string& folder, const std::string& suffix) {
  std::vector<std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const std::string path = entry.path().string();
    if (entry.is_regular_file() && path.size() >= suffix.size() &&
        path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0)
      out.push_back(path);
  }
  std::sort(out.begin(), out.end());
  return out;
}

void expect_golden(const std::string& path, const std::string& actual) {
  const std::string full = corpus_dir() + "/" + path;
  const char* regenerate = std::getenv("FAPC_REGENERATE_GOLDEN");
  if (regenerate && std::string(regenerate) == "1") {
    fs::create_directories(fs::path(full).parent_path());
    std::ofstream(full, std::ios::binary) << actual;
    return;
  }
  if (!fs::exists(full)) {
    ADD_FAILURE() << "golden file " << path << " is missing; run the tests with FAPC_REGENERATE_GOLDEN=1 to create it";
    return;
  }
  EXPECT_EQ(read_text(full), actual) << "golden file " << path << " differs";
}

void expect_generated_region(const std::string& path, const std::string& begin, const std::string& end,
                             const std::string& made, const std::string& source) {
  const std::string full = source_dir() + "/" + path;
  const std::string doc = read_text(full);
  const std::size_t first = doc.find(begin), last = doc.find(end);
  ASSERT_NE(first, std::string::npos) << path << " has no '" << begin << "' marker";
  ASSERT_NE(last, std::string::npos) << path << " has no '" << end << "' marker";
  const std::size_t from = first + begin.size();
  if (const char* regenerate = std::getenv("FAPC_REGENERATE_GOLDEN"); regenerate && std::string(regenerate) == "1") {
    std::ofstream(full, std::ios::binary) << doc.substr(0, from) << made << doc.substr(last);
    return;
  }
  EXPECT_EQ(doc.substr(from, last - from), made) << path << " differs from " << source
                                                 << "; regenerate with FAPC_REGENERATE_GOLDEN=1 (docs/testing.md) "
                                                    "and review the diff";
}

namespace {
std::string slurp_and_remove(const std::string& path) {
  std::string text = read_text(path);
  std::remove(path.c_str());
  return text;
}
}  // namespace

std::string scratch_folder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("fapc-" + name + "-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  return folder.string();
}

CommandRun run_shell(const std::string& command) {
  static int counter = 0;
  const std::string stem =
      (fs::temp_directory_path() / ("fapc-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++)))
          .string();
  const std::string full = "{ " + command + " ; } >'" + stem + ".out' 2>'" + stem + ".err'";
  const int status = std::system(full.c_str());
  CommandRun run;
  run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = slurp_and_remove(stem + ".out");
  run.err = slurp_and_remove(stem + ".err");
  return run;
}

CommandRun run_fapc(const std::string& args) {
  return run_shell("cd '" + source_dir() + "' && '" + fapc_program() + "' " + args);
}

}  // namespace fapc::test

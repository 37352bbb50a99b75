// Ctrl-C in the middle of a batch (docs/cli.md, "Batch"): no new job starts, what finished is
// summed up and reported, and no temporary file is left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

TEST(BatchInterrupt, StopsCleanlyAndStillReports) {
  const fs::path tmp = fs::temp_directory_path() / ("fapc-batch-interrupt-" + std::to_string(::getpid()));
  fs::remove_all(tmp);
  fs::create_directories(tmp / "in");
  // Enough work that the signal comes long before the end: 400 copies of a 1,000-frame script.
  fs::copy_file(test::corpus_dir() + "/examples/mimic/smile.xpr", tmp / "in" / "smile.xpr");  // the script's
  for (int i = 0; i < 400; ++i)
    fs::copy_file(test::corpus_dir() + "/examples/mimic/figure3.mimic",
                  tmp / "in" / ("s" + std::to_string(i) + ".mimic"));
  const std::string out = (tmp / "out").string(), report = (tmp / "report.xml").string();
  const test::CommandRun run =
      test::run_shell("'" + test::fapc_program() + "' batch '" + (tmp / "in").string() + "' -o '" + out +
                      "' --to fap,fba,mp4,svg --jobs 2 --report '" + report + "' > '" + (tmp / "stdout").string() +
                      // The signal comes once the first input is done (its line printed), whatever the machine's load.
                      "' 2>&1 & pid=$!; for i in $(seq 600); do grep -q frames '" + (tmp / "stdout").string() +
                      "' && break; sleep 0.05; done; kill -INT $pid; wait $pid");
  EXPECT_EQ(run.exit_status, 1) << "an interrupted batch did not convert everything";
  const std::string summary = test::read_text((tmp / "stdout").string());
  std::smatch counts;
  ASSERT_TRUE(
      std::regex_search(summary, counts, std::regex(R"((\d+) converted, (\d+) failed, (\d+) not run \(interrupted\))")))
      << summary.substr(summary.size() > 400 ? summary.size() - 400 : 0);
  EXPECT_GT(std::stoi(counts[3]), 0);
  EXPECT_EQ(counts[2], "0");
  const std::string junit = test::read_text(report);
  EXPECT_NE(junit.find("tests=\"" + counts[1].str() + "\" failures=\"0\""), std::string::npos) << junit.substr(0, 200);
  std::size_t leftovers = 0, outputs = 0;
  for (auto entry = fs::recursive_directory_iterator(out); entry != fs::recursive_directory_iterator(); ++entry) {
    if (entry->path().filename() == ".fapc-batch") {  // the completion records (docs/cluster.md)
      entry.disable_recursion_pending();
      continue;
    }
    leftovers += entry->path().filename().string().starts_with(".fapc-tmp-");
    outputs += entry->is_regular_file();
  }
  EXPECT_EQ(leftovers, 0u);
  EXPECT_EQ(outputs, 4u * std::stoul(counts[1]));  // every finished job's four outputs, no others
  fs::remove_all(tmp);
}

}  // namespace
}  // namespace fapc

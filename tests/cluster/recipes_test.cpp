// The recipes of docs/cluster.md run as written where this machine can run them: the Kubernetes
// indexed Job's command line once per completion index, with JOB_COMPLETION_INDEX set as
// Kubernetes sets it. (The Slurm script runs under a real Slurm in slurm_test.sh; the GNU
// parallel lines are console examples, run by the doc-example test.)
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "cluster_test_helpers.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

// The first line of `page` after `marker` that holds `text`, without its leading spaces and "- ".
std::string line_after(const std::string& page, const std::string& marker, const std::string& text) {
  const std::size_t from = page.find(marker);
  if (from == std::string::npos) return {};
  std::istringstream lines(page.substr(from));
  for (std::string line; std::getline(lines, line);) {
    if (line.find(text) == std::string::npos) continue;
    const std::size_t start = line.find_first_not_of(" -");
    return line.substr(start);
  }
  return {};
}

TEST(ClusterRecipes, TheKubernetesJobsPodsTogetherConvertTheWholeBatch) {
  const std::string page = test::read_text(test::source_dir() + "/docs/cluster.md");
  const std::string command = line_after(page, "<!-- kubernetes-job -->", "fapc batch");
  ASSERT_TRUE(command.starts_with("fapc batch corpus -o out ")) << command;
  ASSERT_NE(command.find("--shards 4"), std::string::npos) << command;
  const test::TempFolder tmp;
  // The pod's working folder: the volume with corpus/ in it (here the examples).
  fs::create_directories(tmp / "data/reports");
  fs::create_directory_symlink(test::corpus_dir() + "/examples", tmp / "data/corpus");
  const std::string bin = fs::path(test::fapc_program()).parent_path().string();
  for (int index = 0; index < 4; ++index) {
    const test::CommandRun pod =
        test::run_shell("cd '" + tmp / "data" + "' && PATH='" + bin +
                        "':\"$PATH\" JOB_COMPLETION_INDEX=" + std::to_string(index) + " sh -c '" + command + "'");
    ASSERT_EQ(pod.exit_status, 0) << "pod " << index << ": " << pod.err;
  }
  const test::CommandRun one = test::run_shell("cd '" + tmp / "data" + "' && '" + test::fapc_program() +
                                               "' batch corpus -o '" + tmp / "one" + "' --to fap,fba");
  ASSERT_EQ(one.exit_status, 0) << one.err;
  const auto expected = test::outputs_under(tmp / "one");
  EXPECT_GE(expected.size(), 20u);
  EXPECT_EQ(test::output_differences(tmp / "one", tmp / "data/out"), "");
  const test::CommandRun merged = test::run_shell("cd '" + tmp / "data" + "' && '" + test::fapc_program() +
                                                  "' batch-report merge reports/shard-0.json reports/shard-1.json "
                                                  "reports/shard-2.json reports/shard-3.json");
  EXPECT_EQ(merged.exit_status, 0) << merged.out;
}

}  // namespace
}  // namespace fapc

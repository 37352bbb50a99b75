// `fapc batch` over several machines, run for real on this one (docs/cluster.md): the shards of a
// batch together give exactly the outputs of one batch, whether the shard is given, read from a
// scheduler's environment or the inputs come from a list in any order; a re-run converts only
// what is not finished, also after a task was killed; and the shards' reports merge.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "cluster_test_helpers.hpp"
#include "command/json_schema.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;
using test::fapc_shell;
using test::TempFolder;

// The kinds every test here asks for: cheap ones, one of each writer family.
const std::string kKinds = "--to fap,fba,json";

nlohmann::json read_json(const std::string& path) { return nlohmann::json::parse(test::read_text(path)); }

std::set<std::string> inputs_of(const nlohmann::json& report) {
  std::set<std::string> out;
  for (const auto& job : report["jobs"]) out.insert(job["input"].get<std::string>());
  return out;
}

TEST(ShardedBatch, ThreeShardsGiveExactlyTheOutputsOfOneBatch) {
  const TempFolder tmp;
  const test::CommandRun one = fapc_shell("", "batch corpus/examples -o '" + tmp / "one" + "' " + kKinds);
  ASSERT_EQ(one.exit_status, 0) << one.err;
  std::set<std::string> seen;
  std::size_t jobs = 0;
  for (int i = 0; i < 3; ++i) {
    const std::string report = tmp / ("shard-" + std::to_string(i) + ".json");
    const test::CommandRun shard =
        fapc_shell("", "batch corpus/examples -o '" + tmp / "sharded" + "' " + kKinds + " --shard " +
                           std::to_string(i) + "/3 --report-json '" + report + "'");
    ASSERT_EQ(shard.exit_status, 0) << shard.err;
    const nlohmann::json json = read_json(report);
    EXPECT_EQ(json["shard"]["index"], i);
    EXPECT_EQ(json["shard"]["count"], 3);
    for (const std::string& input : inputs_of(json))
      EXPECT_TRUE(seen.insert(input).second) << input << " in two shards";
    jobs += json["jobs"].size();
    EXPECT_GE(json["jobs"].size(), 1u);
  }
  const auto whole = test::outputs_under(tmp / "one");
  EXPECT_EQ(jobs * 3, whole.size()) << "three outputs per job, each written by one shard";
  EXPECT_EQ(test::output_differences(tmp / "one", tmp / "sharded"), "")
      << "the shards' outputs differ from one batch's";

  // The reports merge into one that matches the schema and names nothing missing.
  const test::CommandRun merged = fapc_shell(
      "", "batch-report merge '" + tmp / "shard-0.json" + "' '" + tmp / "shard-1.json" + "' '" + tmp / "shard-2.json" +
              "' --report-json '" + tmp / "merged.json" + "' --report '" + tmp / "merged.xml" + "'");
  EXPECT_EQ(merged.exit_status, 0) << merged.out << merged.err;
  EXPECT_EQ(merged.out, "3 reports, " + std::to_string(jobs) + " jobs planned: " + std::to_string(jobs) +
                            " converted, 0 up to date, 0 failed, 0 with no result\n");
  const nlohmann::json report = read_json(tmp / "merged.json");
  EXPECT_EQ(test::SchemaFolder(test::source_dir() + "/docs/json").validate(report, "batch-report.schema.json"),
            std::vector<std::string>{});
  EXPECT_EQ(inputs_of(report), seen);
  EXPECT_NE(test::read_text(tmp / "merged.xml").find("tests=\"" + std::to_string(jobs) + "\" failures=\"0\">"),
            std::string::npos);
  // Without shard 1's report, the merge says so and fails.
  const test::CommandRun partial =
      fapc_shell("", "batch-report merge '" + tmp / "shard-0.json" + "' '" + tmp / "shard-2.json" + "'");
  EXPECT_EQ(partial.exit_status, 1);
  EXPECT_NE(partial.out.find("no report: shard 1/3\n"), std::string::npos) << partial.out;
}

TEST(ShardedBatch, TheShardComesFromTheSchedulersEnvironment) {
  const TempFolder tmp;
  const auto shard_inputs = [&](const std::string& environment, const std::string& options) {
    const std::string report = tmp / "report.json";
    const test::CommandRun run = fapc_shell(environment, "batch corpus/examples/fap -o '" + tmp / "out" + "' --force " +
                                                             options + " --report-json '" + report + "'");
    EXPECT_EQ(run.exit_status, 0) << environment << " " << options << "\n" << run.err;
    const nlohmann::json json = read_json(report);
    return std::make_pair(inputs_of(json), json["shard"]);
  };
  const auto given = shard_inputs("", "--shard 1/3");
  EXPECT_EQ(shard_inputs("SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=0", ""), given);
  EXPECT_EQ(shard_inputs("SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=1", "--shards 3"), given);
  EXPECT_EQ(shard_inputs("JOB_COMPLETION_INDEX=1", "--shards 3"), given);
  // --shard wins over the environment.
  EXPECT_EQ(shard_inputs("SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_COUNT=3", "--shard 1/3"), given);
  const test::CommandRun no_count =
      fapc_shell("JOB_COMPLETION_INDEX=1", "batch corpus/examples/fap -o '" + tmp / "x" + "'");
  EXPECT_EQ(no_count.exit_status, 2);
  EXPECT_NE(no_count.err.find("JOB_COMPLETION_INDEX is set: give --shards N"), std::string::npos) << no_count.err;
  EXPECT_FALSE(fs::exists(tmp / "x"));
  const test::CommandRun bad = fapc_shell("", "batch corpus/examples/fap -o '" + tmp / "x" + "' --shard 3/3");
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_NE(bad.err.find("shards count from 0"), std::string::npos) << bad.err;
}

TEST(ShardedBatch, FilesFromAListInAnyOrderPlanTheSameBatch) {
  const TempFolder tmp;
  ASSERT_EQ(fapc_shell("", "batch corpus/examples -o '" + tmp / "walked" + "' " + kKinds + " --report-json '" +
                               tmp / "walked.json" + "'")
                .exit_status,
            0);
  // The planner's list: the walk's inputs, relative to the folder, in reverse order, on standard input.
  std::vector<std::string> listed;
  for (const std::string& input : inputs_of(read_json(tmp / "walked.json")))
    listed.push_back(fs::path(input).lexically_relative("corpus/examples").string());
  ASSERT_GE(listed.size(), 10u);
  std::sort(listed.rbegin(), listed.rend());
  {
    std::ofstream list(tmp / "list.txt");
    for (const std::string& path : listed) list << path << '\n';
  }
  for (int i = 0; i < 3; ++i) {
    const test::CommandRun run =
        fapc_shell("cat '" + tmp / "list.txt" + "' |", "batch corpus/examples --files-from - -o '" + tmp / "listed" +
                                                           "' " + kKinds + " --shard " + std::to_string(i) + "/3");
    ASSERT_EQ(run.exit_status, 0) << run.err;
  }
  EXPECT_EQ(test::output_differences(tmp / "walked", tmp / "listed"), "");
  // A listed path must be a file inside the folder.
  std::ofstream(tmp / "escape.txt") << "../cli/README.md\n";
  const test::CommandRun escape =
      fapc_shell("", "batch corpus/examples --files-from '" + tmp / "escape.txt" + "' -o '" + tmp / "e" + "'");
  EXPECT_EQ(escape.exit_status, 2);
  EXPECT_NE(escape.err.find("is not inside corpus/examples"), std::string::npos) << escape.err;
}

// The counts line of a batch: converted, failed, not run, up to date.
std::vector<int> counts(const std::string& out) {
  std::smatch m;
  const std::regex line(R"((\d+) converted, (\d+) failed, (\d+) not run(, (\d+) up to date)?)");
  if (!std::regex_search(out, m, line)) return {};
  return {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), m[5].matched ? std::stoi(m[5]) : 0};
}

TEST(ResumedBatch, AReRunConvertsOnlyWhatIsNotFinished) {
  const TempFolder tmp;
  fs::copy(test::corpus_dir() + "/examples/fap", tmp / "in");
  const std::string batch = "batch '" + tmp / "in" + "' -o '" + tmp / "out" + "' " + kKinds;
  const test::CommandRun first = fapc_shell("", batch);
  ASSERT_EQ(first.exit_status, 0) << first.err;
  EXPECT_EQ(counts(first.out), (std::vector<int>{5, 0, 0, 0}));
  const auto outputs = test::outputs_under(tmp / "out");
  const auto joy_time = fs::last_write_time(tmp / "out/joy.fba");
  const test::CommandRun again = fapc_shell("", batch);
  EXPECT_EQ(again.exit_status, 0);
  EXPECT_EQ(counts(again.out), (std::vector<int>{0, 0, 0, 5})) << again.out;
  EXPECT_NE(again.out.find(tmp / "in/joy.fap" + ": up to date -> " + tmp / "out/joy.fap"), std::string::npos)
      << again.out;
  EXPECT_EQ(fs::last_write_time(tmp / "out/joy.fba"), joy_time) << "an up-to-date output was rewritten";
  // An input changed, an output removed: those two jobs again.
  fs::last_write_time(tmp / "in/anger.fap", fs::last_write_time(tmp / "in/anger.fap") + std::chrono::seconds(10));
  fs::remove(tmp / "out/vreng-joy.json");
  EXPECT_EQ(counts(fapc_shell("", batch).out), (std::vector<int>{2, 0, 0, 3}));
  EXPECT_TRUE(test::outputs_under(tmp / "out") == outputs);
  // Other options change the outputs: everything again; --force: everything again.
  EXPECT_EQ(counts(fapc_shell("", batch + " --fps 30").out), (std::vector<int>{5, 0, 0, 0}));
  EXPECT_EQ(counts(fapc_shell("", batch + " --fps 30").out), (std::vector<int>{0, 0, 0, 5}));
  EXPECT_EQ(counts(fapc_shell("", batch + " --fps 30 --force").out), (std::vector<int>{5, 0, 0, 0}));
  // The options that only say how to run (jobs, reports) keep the records valid.
  EXPECT_EQ(counts(fapc_shell("", batch + " --fps 30 --jobs 1 --report '" + tmp / "r.xml" + "'").out),
            (std::vector<int>{0, 0, 0, 5}));
}

TEST(ResumedBatch, AKilledRunResumesWithoutRedoingFinishedJobs) {
  const TempFolder tmp;
  // 120 jobs, one at a time: long enough to be killed in the middle on any machine.
  fs::create_directories(tmp / "in");
  for (int i = 0; i < 120; ++i)
    fs::copy_file(test::corpus_dir() + "/examples/fap/joy.fap", tmp / ("in/s" + std::to_string(100 + i) + ".fap"));
  const std::string out = tmp / "out", records = tmp / "out/.fapc-batch";
  const std::string batch = "batch '" + tmp / "in" + "' -o '" + out + "' --to fap,fba,json,svg --jobs 1";
  // SIGKILL (no chance to clean up) once a few jobs have their completion records.
  const test::CommandRun killed = fapc_shell(
      "", batch + " --report-json '" + tmp / "killed.json" +
              "' > /dev/null 2>&1 & pid=$!; for i in $(seq 1200); do "
              "[ $(ls '" +
              records + "' 2>/dev/null | wc -l) -ge 3 ] && break; sleep 0.01; done; kill -KILL $pid; wait $pid");
  EXPECT_EQ(killed.exit_status, 128 + 9) << "the run ended before it was killed: make it longer";
  std::size_t finished_before = 0;
  // A record being written when the kill came is a temporary file (".fapc-tmp-...-s104.fap.done"),
  // not a record: it does not count.
  for (const auto& entry : fs::directory_iterator(records))
    finished_before +=
        entry.path().extension() == ".done" && !entry.path().filename().string().starts_with(".fapc-tmp-");
  ASSERT_GE(finished_before, 3u);
  ASSERT_LT(finished_before, 120u);
  // The report written at the start names every job of the killed run as not run.
  const test::CommandRun merge_killed = fapc_shell("", "batch-report merge '" + tmp / "killed.json" + "'");
  EXPECT_EQ(merge_killed.exit_status, 1);
  EXPECT_NE(merge_killed.out.find("no result: " + tmp / "in/s100.fap"), std::string::npos) << merge_killed.out;
  // A killed attempt's temporary file for one of the jobs, as a SIGKILL mid-write leaves it.
  std::ofstream(out + "/.fapc-tmp-99999-1-0-s219.fba") << "half an output";

  const test::CommandRun resumed = fapc_shell("", batch + " --report-json '" + tmp / "resumed.json" + "'");
  ASSERT_EQ(resumed.exit_status, 0) << resumed.err;
  const std::vector<int> n = counts(resumed.out);
  ASSERT_EQ(n.size(), 4u) << resumed.out;
  EXPECT_GE(n[3], static_cast<int>(finished_before)) << "finished jobs were converted again";
  EXPECT_EQ(n[0] + n[3], 120);
  EXPECT_EQ(n[1] + n[2], 0);
  // Nothing lost, nothing twice, nothing left over: the outputs of one clean batch.
  ASSERT_EQ(fapc_shell("", "batch '" + tmp / "in" + "' -o '" + tmp / "clean" + "' --to fap,fba,json,svg").exit_status,
            0);
  const auto expected = test::outputs_under(tmp / "clean");
  EXPECT_EQ(expected.size(), 480u);
  const auto got = test::outputs_under(out);
  EXPECT_EQ(got.size(), expected.size());
  for (const auto& [path, bytes] : got) EXPECT_TRUE(expected.count(path) && expected.at(path) == bytes) << path;
  const auto merged = fapc_shell("", "batch-report merge '" + tmp / "resumed.json" + "'");
  EXPECT_EQ(merged.exit_status, 0) << merged.out;
}

}  // namespace
}  // namespace fapc

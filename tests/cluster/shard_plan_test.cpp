// Shards, completion records and merged reports as library functions (fapc::pipeline,
// batch_shard.hpp, batch_resume.hpp, batch_merge.hpp): every job in exactly one shard whatever
// the listing order, the scheduler's environment read as docs/cluster.md says, records that go
// stale when their input or output changes, and merges that name what has no result.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "cluster_test_helpers.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/batch_merge.hpp"
#include "fapc/pipeline/batch_resume.hpp"
#include "fapc/pipeline/batch_shard.hpp"

namespace fapc {
namespace {

using pipeline::BatchJob;
using pipeline::Shard;

std::vector<BatchJob> jobs_named(int count) {
  std::vector<BatchJob> jobs;
  for (int i = 0; i < count; ++i) {
    const std::string name = "d" + std::to_string(i % 7) + "/f" + std::to_string(i);
    jobs.push_back({"in/" + name + ".fap", {{"out/" + name + ".fba", "fba"}, {"out/" + name + ".svg", "svg"}}});
  }
  return jobs;
}

TEST(ShardPlan, ParsesIOfN) {
  const auto shard = pipeline::parse_shard("2/3");
  ASSERT_TRUE(shard);
  EXPECT_EQ(shard->index, 2u);
  EXPECT_EQ(shard->count, 3u);
  for (const char* bad : {"3/3", "1/0", "x/3", "1", "1/", "/3", "-1/3", "1/3/4", " 1/3", "1/100001"})
    EXPECT_FALSE(pipeline::parse_shard(bad)) << bad;
  EXPECT_NE(pipeline::parse_shard("3/3").error().message.find("count from 0"), std::string::npos);
}

TEST(ShardPlan, EveryJobIsInExactlyOneShardWhateverTheOrder) {
  const std::vector<BatchJob> jobs = jobs_named(101);
  std::vector<BatchJob> shuffled = jobs;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  for (const std::size_t count : {1u, 2u, 3u, 4u, 200u}) {
    std::map<std::string, std::size_t> shard_of;
    std::size_t smallest = jobs.size(), largest = 0;
    for (std::size_t index = 0; index < count; ++index) {
      const auto mine = pipeline::select_shard(jobs, Shard{index, count});
      const auto mine_shuffled = pipeline::select_shard(shuffled, Shard{index, count});
      std::set<std::string> a, b;
      for (const BatchJob& job : mine) a.insert(job.input);
      for (const BatchJob& job : mine_shuffled) b.insert(job.input);
      EXPECT_EQ(a, b) << "shard " << index << "/" << count << " depends on the listing order";
      for (const std::string& input : a)
        EXPECT_TRUE(shard_of.emplace(input, index).second) << input << " in two shards";
      smallest = std::min(smallest, a.size());
      largest = std::max(largest, a.size());
      // Within a shard, jobs keep the plan's order.
      for (std::size_t i = 1; i < mine.size(); ++i)
        EXPECT_LT(
            std::find_if(jobs.begin(), jobs.end(), [&](const BatchJob& j) { return j.input == mine[i - 1].input; }),
            std::find_if(jobs.begin(), jobs.end(), [&](const BatchJob& j) { return j.input == mine[i].input; }));
    }
    EXPECT_EQ(shard_of.size(), jobs.size()) << count << " shards lose jobs";
    EXPECT_LE(largest - smallest, 1u) << count << " shards are uneven";
  }
}

// A fake environment: the variables a scheduler would set.
pipeline::EnvironmentLookup environment(std::map<std::string, std::string> variables) {
  return [variables = std::move(variables)](const char* name) -> const char* {
    const auto it = variables.find(name);
    return it == variables.end() ? nullptr : it->second.c_str();
  };
}

TEST(ShardPlan, ShardFromTheSchedulersEnvironment) {
  const auto shard = [](std::map<std::string, std::string> variables, std::optional<std::size_t> shards = {}) {
    return pipeline::shard_from_environment(environment(std::move(variables)), shards);
  };
  EXPECT_FALSE(*shard({}));  // no scheduler: the whole batch
  auto slurm = shard({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
  ASSERT_TRUE(slurm && *slurm);
  EXPECT_EQ((*slurm)->index, 2u);
  EXPECT_EQ((*slurm)->count, 4u);
  // --array=1-4: task 1 is shard 0; --array=0-6:2: task 4 is shard 2 of 4.
  auto from_one = shard({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}, {"SLURM_ARRAY_TASK_MIN", "1"}});
  ASSERT_TRUE(from_one && *from_one);
  EXPECT_EQ((*from_one)->index, 0u);
  auto stepped = shard({{"SLURM_ARRAY_TASK_ID", "4"},
                        {"SLURM_ARRAY_TASK_COUNT", "4"},
                        {"SLURM_ARRAY_TASK_MIN", "0"},
                        {"SLURM_ARRAY_TASK_STEP", "2"}});
  ASSERT_TRUE(stepped && *stepped);
  EXPECT_EQ((*stepped)->index, 2u);
  // A task resubmitted alone (--array=2: a count of 1) keeps its shard with --shards.
  auto alone = shard({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "1"}, {"SLURM_ARRAY_TASK_MIN", "2"}}, 4);
  ASSERT_TRUE(alone && *alone);
  EXPECT_EQ((*alone)->index, 2u);
  EXPECT_EQ((*alone)->count, 4u);
  auto pod = shard({{"JOB_COMPLETION_INDEX", "3"}}, 5);
  ASSERT_TRUE(pod && *pod);
  EXPECT_EQ((*pod)->index, 3u);
  EXPECT_EQ((*pod)->count, 5u);
  EXPECT_FALSE(shard({{"JOB_COMPLETION_INDEX", "3"}}));     // the count is not in a pod's environment
  EXPECT_FALSE(shard({{"JOB_COMPLETION_INDEX", "5"}}, 5));  // out of range
  EXPECT_FALSE(shard({{"SLURM_ARRAY_TASK_ID", "x"}}));      // not a number
  EXPECT_FALSE(shard({{"SLURM_ARRAY_TASK_ID", "1"}}));      // no count
  EXPECT_FALSE(shard({}, 4));                               // --shards without an index
  EXPECT_EQ(shard({{"JOB_COMPLETION_INDEX", "1"}}).error().kind, ErrorKind::usage);
}

TEST(CompletionRecords, AJobIsCompleteUntilItsInputOrAnOutputChanges) {
  const test::TempFolder tmp;
  std::filesystem::create_directories(tmp / "out/sub");
  std::ofstream(tmp / "in.fap") << "input";
  const BatchJob job{tmp / "in.fap", {{tmp / "out/sub/in.fba", "fba"}, {tmp / "out/sub/in.svg", "svg"}}};
  const auto write_outputs = [&] {
    for (const auto& output : job.outputs) std::ofstream(output.path) << "output of " << output.kind;
  };
  const pipeline::CompletionRecords records(tmp / "out", "--fps=25", {job});
  EXPECT_EQ(records.record_path(job), tmp / "out/.fapc-batch/sub/in.fba.done");
  EXPECT_EQ(pipeline::CompletionRecords(tmp / "out/", "", {job}).record_path(job),
            tmp / "out/.fapc-batch/sub/in.fba.done")
      << "-o with a final slash";
  EXPECT_FALSE(records.complete(job));  // no record
  write_outputs();
  EXPECT_FALSE(records.complete(job)) << "outputs without a record are not taken for finished";
  auto stamp = records.prepare(job);
  write_outputs();
  ASSERT_TRUE(records.record(job, stamp));
  EXPECT_TRUE(records.complete(job));
  EXPECT_FALSE(pipeline::CompletionRecords(tmp / "out", "--fps=30", {job}).complete(job)) << "other settings";
  // An output rewritten (another size) or removed: not complete.
  std::ofstream(job.outputs[1].path) << "a different, longer output";
  EXPECT_FALSE(records.complete(job));
  stamp = records.prepare(job);
  EXPECT_FALSE(std::filesystem::exists(records.record_path(job))) << "a job being redone has no record";
  write_outputs();
  ASSERT_TRUE(records.record(job, stamp));
  EXPECT_TRUE(records.complete(job));
  std::filesystem::remove(job.outputs[0].path);
  EXPECT_FALSE(records.complete(job));
  // The input changed after its outputs were made.
  stamp = records.prepare(job);
  write_outputs();
  ASSERT_TRUE(records.record(job, stamp));
  std::filesystem::last_write_time(job.input, std::filesystem::last_write_time(job.input) + std::chrono::seconds(5));
  EXPECT_FALSE(records.complete(job));
  // A damaged record is no record.
  stamp = records.prepare(job);
  write_outputs();
  ASSERT_TRUE(records.record(job, stamp));
  std::ofstream(records.record_path(job)) << "{\"input\": ";
  EXPECT_FALSE(records.complete(job));
}

TEST(CompletionRecords, PrepareRemovesOnlyThisJobsLeftovers) {
  const test::TempFolder tmp;
  std::filesystem::create_directories(tmp / "out");
  std::ofstream(tmp / "in.fap") << "input";
  const BatchJob job{tmp / "in.fap", {{tmp / "out/in.fba", "fba"}}};
  // A killed attempt's temporary file for this job, and another shard's for its own job.
  std::ofstream(tmp / "out/.fapc-tmp-123-456-0-in.fba") << "half";
  std::ofstream(tmp / "out/.fapc-tmp-124-457-0-other.fba") << "half";
  std::ofstream(tmp / "out/.fapc-tmp-x-in.fba") << "not a name fapc makes";
  // This process's own, which another of its threads may be writing while the sweep walks the
  // folder (it was removed under it, and that job failed "cannot replace output").
  const std::string writing = tmp / ("out/" + own_temporary_prefix() + "7-in.fba");
  std::ofstream(writing) << "being written";
  const pipeline::CompletionRecords records(tmp / "out", "", {job});
  records.prepare(job);
  EXPECT_FALSE(std::filesystem::exists(tmp / "out/.fapc-tmp-123-456-0-in.fba"));
  EXPECT_TRUE(std::filesystem::exists(tmp / "out/.fapc-tmp-124-457-0-other.fba"));
  EXPECT_TRUE(std::filesystem::exists(tmp / "out/.fapc-tmp-x-in.fba"));
  EXPECT_TRUE(std::filesystem::exists(writing));
}

// A shard's report as `fapc batch --report-json` writes it, reduced to what the merge reads.
std::string report(std::size_t index, std::size_t count, std::size_t planned,
                   const std::vector<std::pair<std::string, std::string>>& jobs) {
  nlohmann::ordered_json out = {
      {"schema_version", 1}, {"shard", {{"index", index}, {"count", count}}}, {"planned", planned}};
  out["jobs"] = nlohmann::ordered_json::array();
  for (const auto& [input, state] : jobs) {
    const bool ran = state == "converted" || state == "failed";
    nlohmann::ordered_json job = {{"input", input},
                                  {"ran", ran},
                                  {"up_to_date", state == "up_to_date"},
                                  {"ok", state == "converted" || state == "up_to_date"},
                                  {"seconds", 0.5},
                                  {"outputs", {"out/" + input + ".fba"}},
                                  {"written", nlohmann::ordered_json::array()}};
    job["error"] = state == "failed"
                       ? nlohmann::ordered_json{{"kind", "bad_input"}, {"text", input + ": error: bad <x>"}}
                       : nlohmann::ordered_json(nullptr);
    job["warnings"] = nlohmann::ordered_json::array();
    out["jobs"].push_back(job);
  }
  out["totals"] = {{"interrupted", false}};
  return out.dump();
}

TEST(MergeReports, EveryPlannedJobGetsItsBestResult) {
  const std::vector<pipeline::ReportText> reports = {
      {"s0.json", report(0, 3, 6, {{"a", "converted"}, {"d", "failed"}})},
      {"s1.json", report(1, 3, 6, {{"b", "up_to_date"}, {"e", "not_run"}})},
      {"s2.json", report(2, 3, 6, {{"c", "converted"}, {"f", "not_run"}})},
      // Shard 2 run again after it was killed: f now converted, c still up to date.
      {"s2-again.json", report(2, 3, 6, {{"c", "up_to_date"}, {"f", "converted"}})},
  };
  auto merged = pipeline::merge_batch_reports(reports);
  ASSERT_TRUE(merged) << merged.error().message;
  EXPECT_EQ(merged->failed, std::vector<std::string>{"d"});
  EXPECT_EQ(merged->no_result, std::vector<std::string>{"e"});
  EXPECT_TRUE(merged->missing_shards.empty());
  EXPECT_FALSE(merged->complete());
  const auto& totals = merged->report["totals"];
  EXPECT_EQ(totals["jobs"], 6);
  EXPECT_EQ(totals["converted"], 3);  // a, c (converted beats up to date), f
  EXPECT_EQ(totals["up_to_date"], 1);
  EXPECT_EQ(totals["failed"], 1);
  EXPECT_EQ(totals["not_run"], 1);
  std::vector<std::string> inputs;
  for (const auto& job : merged->report["jobs"]) inputs.push_back(job["input"].get<std::string>());
  EXPECT_EQ(inputs, (std::vector<std::string>{"a", "b", "c", "d", "e", "f"}));
  const std::string junit = pipeline::junit_from_report(merged->report);
  EXPECT_NE(junit.find("tests=\"6\" failures=\"1\" errors=\"1\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("message=\"d: error: bad &lt;x&gt;\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("<testcase name=\"e\" time=\"0\"><error type=\"no_result\""), std::string::npos) << junit;
}

TEST(MergeReports, MissingShardsAndMismatchesAreSaid) {
  auto merged = pipeline::merge_batch_reports(
      {{"s0.json", report(0, 3, 3, {{"a", "converted"}})}, {"s2.json", report(2, 3, 3, {{"c", "converted"}})}});
  ASSERT_TRUE(merged);
  EXPECT_EQ(merged->missing_shards, std::vector<std::size_t>{1});
  EXPECT_EQ(merged->unnamed_without_result, 1u);
  EXPECT_EQ(merged->report["totals"]["not_run"], 1);
  EXPECT_NE(pipeline::junit_from_report(merged->report).find("name=\"shard 1/3\""), std::string::npos);
  auto counts = pipeline::merge_batch_reports({{"s0.json", report(0, 3, 3, {})}, {"t.json", report(0, 4, 3, {})}});
  ASSERT_FALSE(counts);
  EXPECT_EQ(counts.error().kind, ErrorKind::usage);
  EXPECT_EQ(counts.error().where.file, "t.json");
  EXPECT_FALSE(pipeline::merge_batch_reports({{"s0.json", report(0, 2, 3, {})}, {"t.json", report(1, 2, 4, {})}}));
  auto broken = pipeline::merge_batch_reports({{"bad.json", "{\"jobs\": [1,"}});
  ASSERT_FALSE(broken);
  EXPECT_EQ(broken.error().where.file, "bad.json");
  EXPECT_GE(broken.error().where.byte_offset, 10);
  EXPECT_FALSE(pipeline::merge_batch_reports({{"other.json", "{\"schema_version\": 1, \"files\": []}"}}));
  EXPECT_FALSE(pipeline::merge_batch_reports({}));
}

}  // namespace
}  // namespace fapc

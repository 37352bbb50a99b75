// Batch planning and running: outputs mirror the input tree, shared outputs and an output
// folder that is a file are refused before anything runs, outputs are never inputs, and jobs
// are handed over in input order whatever order they finish in.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/batch.hpp"
#include "pipeline_test_helpers.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

void copy_example(const std::string& example, const std::string& to) {
  fs::create_directories(fs::path(to).parent_path());
  fs::copy_file(test::corpus_dir() + "/examples/" + example, to, fs::copy_options::overwrite_existing);
}

TEST(BatchPlan, OutputsMirrorTheInputTree) {
  const test::TempFolder tmp;
  copy_example("fap/joy.fap", tmp / "in/a/joy.fap");
  copy_example("fap/anger.fap", tmp / "in/b/c/anger.fap");
  auto jobs = pipeline::plan_batch({tmp / "in"}, tmp / "out", {"fap", "json"});
  ASSERT_TRUE(jobs) << jobs.error().message;
  ASSERT_EQ(jobs->size(), 2u);
  EXPECT_EQ((*jobs)[0].input, tmp / "in/a/joy.fap");
  EXPECT_EQ((*jobs)[0].outputs[0].path, tmp / "out/a/joy.fap");
  EXPECT_EQ((*jobs)[0].outputs[1].path, tmp / "out/a/joy.json");
  EXPECT_EQ((*jobs)[1].outputs[0].path, tmp / "out/b/c/anger.fap");
}

TEST(BatchPlan, AFoldersInputsThatDifferByExtensionOnlyKeepIt) {
  const test::TempFolder tmp;
  copy_example("fap/joy.fap", tmp / "in/a/joy.fap");
  copy_example("fap/joy.fap", tmp / "in/a/joy.fap.gz");  // not compressed: planning reads no file
  copy_example("fap/anger.fap", tmp / "in/a/anger.fap");
  auto jobs = pipeline::plan_batch({tmp / "in"}, tmp / "out", {"fba"});
  ASSERT_TRUE(jobs) << jobs.error().message;
  ASSERT_EQ(jobs->size(), 3u);
  EXPECT_EQ((*jobs)[0].outputs[0].path, tmp / "out/a/anger.fba");
  EXPECT_EQ((*jobs)[1].outputs[0].path, tmp / "out/a/joy.fap.fba");
  EXPECT_EQ((*jobs)[2].outputs[0].path, tmp / "out/a/joy.fap.gz.fba");
}

TEST(BatchPlan, TwoInputsForOneOutputAreRefusedAndListed) {
  const test::TempFolder tmp;
  copy_example("fap/joy.fap", tmp / "a/x.fap");
  copy_example("fap/joy.fap", tmp / "b/x.fap");
  auto jobs = pipeline::plan_batch({tmp / "a/x.fap", tmp / "b/x.fap"}, tmp / "out", {"fba"});
  ASSERT_FALSE(jobs);
  EXPECT_EQ(jobs.error().kind, ErrorKind::usage);
  const std::string& message = jobs.error().message;
  EXPECT_NE(message.find(tmp / "out/x.fba"), std::string::npos) << message;
  EXPECT_NE(message.find(tmp / "a/x.fap"), std::string::npos) << message;
  EXPECT_NE(message.find(tmp / "b/x.fap"), std::string::npos) << message;
}

TEST(BatchPlan, AnOutputFolderThatIsAFileIsAUsageError) {
  const test::TempFolder tmp;
  ASSERT_TRUE(write_file_atomic(tmp / "taken", "x"));
  auto jobs = pipeline::plan_batch({test::corpus_dir() + "/examples/fap"}, tmp / "taken", {"fap"});
  ASSERT_FALSE(jobs);
  EXPECT_EQ(jobs.error().kind, ErrorKind::usage);
}

TEST(BatchPlan, FilesUnderTheOutputFolderAreNeverInputs) {
  const test::TempFolder tmp;
  copy_example("fap/joy.fap", tmp / "joy.fap");
  copy_example("fap/anger.fap", tmp / "out/anger.fap");  // an output of an earlier run
  auto jobs = pipeline::plan_batch({tmp.path().string()}, tmp / "out", {"fba"});
  ASSERT_TRUE(jobs) << jobs.error().message;
  ASSERT_EQ(jobs->size(), 1u);
  EXPECT_EQ((*jobs)[0].input, tmp / "joy.fap");
}

TEST(BatchRun, FailuresAreCountedAndTheOthersRunWithKeepGoing) {
  const test::TempFolder tmp;
  for (const char* name : {"a", "b", "c", "d", "e", "f"})
    copy_example("fap/joy.fap", tmp / (std::string("in/") + name + ".fap"));
  ASSERT_TRUE(write_file_atomic(tmp / "in/c.fap", "not a fap file"));
  auto jobs = pipeline::plan_batch({tmp / "in"}, tmp / "out", {"fap", "fba"});
  ASSERT_TRUE(jobs);
  pipeline::BatchRunOptions run;
  run.threads = 3;
  run.keep_going = true;
  std::vector<std::size_t> order;
  run.in_order = [&](std::size_t index, const pipeline::BatchOutcome&) { order.push_back(index); };
  const auto outcomes = pipeline::run_batch(*jobs, {}, run);
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
  ASSERT_EQ(outcomes.size(), 6u);
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    EXPECT_TRUE(outcomes[i].ran);
    EXPECT_EQ(outcomes[i].result.ok(), i != 2) << i;
  }
  EXPECT_FALSE(fs::exists(tmp / "out/c.fap"));
  EXPECT_TRUE(fs::exists(tmp / "out/f.fba"));
  const std::string junit = pipeline::junit_report(*jobs, outcomes);
  EXPECT_NE(junit.find("tests=\"6\" failures=\"1\""), std::string::npos) << junit;
}

TEST(BatchRun, AJobThatThrowsIsAFailedJobAndTheOthersStillRun) {
  auto jobs = pipeline::plan_batch({test::corpus_dir() + "/examples/fap"}, "/nonexistent-out", {"fap"});
  ASSERT_TRUE(jobs);
  ASSERT_GE(jobs->size(), 3u);
  pipeline::BatchRunOptions run;
  run.threads = 2;
  run.keep_going = true;
  run.convert = [&](const pipeline::BatchJob& job, const pipeline::ConvertOptions&) {
    if (job.input == (*jobs)[1].input) throw std::runtime_error("boom");
    return pipeline::ConvertResult{};
  };
  const auto outcomes = pipeline::run_batch(*jobs, {}, run);
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    EXPECT_TRUE(outcomes[i].ran) << i;
    EXPECT_EQ(outcomes[i].result.ok(), i != 1) << i;
  }
  ASSERT_TRUE(outcomes[1].result.error);
  EXPECT_NE(outcomes[1].result.error->message.find("boom"), std::string::npos);
  EXPECT_EQ(outcomes[1].result.error->where.file, (*jobs)[1].input);
}

TEST(BatchRun, AStopSetBeforehandRunsNothing) {
  auto jobs = pipeline::plan_batch({test::corpus_dir() + "/examples/fap"}, "/nonexistent-out", {"fap"});
  ASSERT_TRUE(jobs);
  std::atomic<bool> stop{true};
  pipeline::BatchRunOptions run;
  run.stop = &stop;
  for (const auto& outcome : pipeline::run_batch(*jobs, {}, run)) EXPECT_FALSE(outcome.ran);
}

// `--to wav` over inputs without a voice fails every job: the output folders the batch made for
// them go again (a failed batch leaves nothing, as a failed compile does); a folder that was
// there before stays.
TEST(BatchRun, FoldersMadeForOutputsNoneWroteAreRemoved) {
  const test::TempFolder tmp;
  copy_example("fap/joy.fap", tmp / "in/a/joy.fap");
  copy_example("fap/anger.fap", tmp / "in/b/c/anger.fap");
  auto jobs = pipeline::plan_batch({tmp / "in"}, tmp / "out", {"wav"});
  ASSERT_TRUE(jobs) << jobs.error().message;
  pipeline::BatchRunOptions run;
  run.keep_going = true;
  for (const auto& outcome : pipeline::run_batch(*jobs, {}, run)) EXPECT_FALSE(outcome.result.ok());
  EXPECT_FALSE(fs::exists(tmp / "out"));
  fs::create_directories(tmp / "kept");
  jobs = pipeline::plan_batch({tmp / "in"}, tmp / "kept", {"wav"});
  ASSERT_TRUE(jobs);
  pipeline::run_batch(*jobs, {}, run);
  EXPECT_TRUE(fs::is_directory(tmp / "kept"));
  EXPECT_TRUE(fs::is_empty(tmp / "kept"));
}

// When some jobs succeed, only the folders of the failed ones go.
TEST(BatchRun, OnlyTheEmptyFoldersGo) {
  const test::TempFolder tmp;
  copy_example("fap/joy.fap", tmp / "in/a/joy.fap");
  fs::create_directories(tmp / "in/b");
  ASSERT_TRUE(write_file_atomic(tmp / "in/b/bad.fap", "not a fap file"));
  auto jobs = pipeline::plan_batch({tmp / "in"}, tmp / "out", {"fap"});
  ASSERT_TRUE(jobs);
  pipeline::BatchRunOptions run;
  run.keep_going = true;
  pipeline::run_batch(*jobs, {}, run);
  EXPECT_TRUE(fs::exists(tmp / "out/a/joy.fap"));
  EXPECT_FALSE(fs::exists(tmp / "out/b"));
}

}  // namespace
}  // namespace fapc

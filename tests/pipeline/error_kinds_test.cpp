// Typical failures and the kind and code each one carries: the kind and the code (docs/errors.md),
// not the wording, are what callers (the program's exit status, a batch's summary) decide by.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/verify.hpp"
#include "fapc/timeline/schedule.hpp"
#include "pipeline_test_helpers.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

using pipeline::ConvertOptions;

ErrorKind load_error_kind(const std::string& path) {
  auto loaded = pipeline::load(path, ConvertOptions{});
  EXPECT_FALSE(loaded) << path;
  return loaded ? ErrorKind::bad_input : loaded.error().kind;
}

std::string load_error_code(const std::string& path) {
  auto loaded = pipeline::load(path, ConvertOptions{});
  return loaded ? "(loaded)" : loaded.error().code;
}

TEST(ErrorKinds, AMissingFileIsIo) {
  EXPECT_EQ(load_error_kind("/nonexistent/x.fap"), ErrorKind::io);
  EXPECT_EQ(load_error_code("/nonexistent/x.fap"), "io.cannot_open");
}

TEST(ErrorKinds, AnUnknownExtensionIsUnsupported) {
  EXPECT_EQ(load_error_kind(test::corpus_dir() + "/catalog.tsv"), ErrorKind::unsupported);
  EXPECT_EQ(load_error_code(test::corpus_dir() + "/catalog.tsv"), "format.unknown_extension");
  const auto result = pipeline::convert(test::corpus_dir() + "/examples/fap/anger.fap", {{"x.unknown", ""}}, {});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error->kind, ErrorKind::unsupported);
  EXPECT_EQ(result.error->code, "format.unknown_extension");
}

TEST(ErrorKinds, AStreamCutShortIsTruncated) {
  const test::TempFolder tmp;
  ASSERT_TRUE(pipeline::convert(test::corpus_dir() + "/examples/fap/anger.fap", {{tmp / "a.fba", ""}}, {}).ok());
  const std::string whole = test::read_text(tmp / "a.fba");
  ASSERT_TRUE(write_file_atomic(tmp / "cut.fba", whole.substr(0, whole.size() / 2)));
  EXPECT_EQ(load_error_kind(tmp / "cut.fba"), ErrorKind::truncated);
  EXPECT_EQ(load_error_code(tmp / "cut.fba"), "fba.truncated");
}

TEST(ErrorKinds, AStreamFapcDidNotWriteFailsVerification) {
  // The reference encoder's stream with time codes decodes, but fapc writes other bytes for it.
  const auto verified = pipeline::verify(test::corpus_dir() + "/fba/time-code-29.97fps.fba", {});
  ASSERT_FALSE(verified.ok());
  EXPECT_EQ(verified.error->kind, ErrorKind::verification_failed);
  EXPECT_EQ(verified.error->code, "verify.fba_foreign");
}

TEST(ErrorKinds, AStoryThatNeverEndsIsBadInputAtTheElement) {
  auto loaded = pipeline::load(test::corpus_dir() + "/fml-bad/indefinite-without-end.fml", {});
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().kind, ErrorKind::bad_input);
  EXPECT_EQ(loaded.error().code, "timeline.endless_repeat");
  EXPECT_EQ(loaded.error().where.line, 2);
  EXPECT_EQ(loaded.error().message.substr(0, 7), "action ");
}

// The scheduler's problems are values: which problem, and the front end's tag of the node.
TEST(ScheduleErrors, CarryTheProblemAndTheNodesTag) {
  Timing forever;
  forever.repeat_indefinite = true;
  ScheduleNode root = ScheduleNode::group(ScheduleNode::Kind::sequence, {}, Location::text("f", 1, 1));
  root.tag = 1;
  ScheduleNode leaf = ScheduleNode::leaf(0, Timing{}, Location::text("f", 2, 3));
  leaf.tag = 7;
  root.children.push_back(leaf);
  auto scheduled = schedule_tree(root);
  const auto* problem = std::get_if<ScheduleError>(&scheduled);
  ASSERT_NE(problem, nullptr);
  EXPECT_EQ(problem->problem, ScheduleProblem::no_duration);
  EXPECT_EQ(problem->node_tag, 7u);
  EXPECT_EQ(problem->where.line, 2);
  EXPECT_TRUE(problem->needs_an_end());

  Timing tiny;
  tiny.duration = 0.001;
  tiny.repeat = 10;
  ScheduleNode repeated = ScheduleNode::leaf(0, tiny, Location::text("f", 3, 1));
  repeated.tag = 9;
  ScheduleOptions few;
  few.max_runs = 3;
  auto too_many = schedule_tree(repeated, few);
  const auto* limit = std::get_if<ScheduleError>(&too_many);
  ASSERT_NE(limit, nullptr);
  EXPECT_EQ(limit->problem, ScheduleProblem::too_many_runs);
  EXPECT_EQ(limit->node_tag, 9u);
  EXPECT_EQ(limit->diagnostic("clip").kind, ErrorKind::limit_exceeded);
}

}  // namespace
}  // namespace fapc

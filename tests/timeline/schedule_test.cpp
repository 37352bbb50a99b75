// The scheduler against timings worked out by hand (docs/timeline.md).
#include <gtest/gtest.h>

#include "fapc/timeline/schedule.hpp"

namespace fapc {
namespace {

using Kind = ScheduleNode::Kind;

ScheduleNode leaf(std::size_t id, std::optional<double> duration, double offset = 0) {
  Timing timing;
  timing.duration = duration;
  timing.offset = offset;
  return ScheduleNode::leaf(id, timing, Location::text("t.mimic", static_cast<int>(id) + 1, 1));
}

ScheduleNode group(Kind kind, std::vector<ScheduleNode> children, Timing timing = {}) {
  ScheduleNode node = ScheduleNode::group(kind, timing, Location::text("t.mimic", 100, 1));
  node.children = std::move(children);
  return node;
}

// (leaf, begin, end) triples, the form the expectations are written in.
std::vector<std::tuple<std::size_t, double, double>> spans(const Schedule& s) {
  std::vector<std::tuple<std::size_t, double, double>> out;
  for (const Occurrence& o : s.occurrences) out.emplace_back(o.leaf_id, o.begin, o.end);
  return out;
}

using Spans = std::vector<std::tuple<std::size_t, double, double>>;

TEST(Schedule, SequenceRunsChildrenBackToBack) {
  const auto s = schedule(group(Kind::sequence, {leaf(0, 2), leaf(1, 3)}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 2}, {1, 2, 5}}));
  EXPECT_EQ(s->end, 5);
}

TEST(Schedule, NegativeLeftOverlapsThePredecessorAndTheLatestEndEndsTheSequence) {
  // 0: [0,4); 1 starts at 4-3=1 and lasts 1: [1,2). The sequence ends at 4, not 2.
  const auto s = schedule(group(Kind::sequence, {leaf(0, 4), leaf(1, 1, -3), leaf(2, 1)}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 4}, {1, 1, 2}, {2, 2, 3}}));
  EXPECT_EQ(s->end, 4);
}

TEST(Schedule, StartBeforeZeroIsAnErrorAtTheLeaf) {
  const auto s = schedule(group(Kind::sequence, {leaf(0, 1), leaf(1, 1, -2)}));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().where.line, 2);
  EXPECT_EQ(s.error().message, "the action starts before time 0 (at -1 s)");
}

TEST(Schedule, ParallelStretchesOpenChildrenToTheReferenceEnd) {
  // Reference end 5 (the longest known child); the periodic child 2 spans [1, 5).
  const auto s = schedule(group(Kind::parallel, {leaf(0, 2), leaf(1, 5), leaf(2, {}, 1)}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 2}, {1, 0, 5}, {2, 1, 5}}));
}

TEST(Schedule, RightAlignmentEndsAtTheReferenceEndPlusPadding) {
  ScheduleNode right0 = leaf(1, 1);
  right0.timing.align_right = 0;
  ScheduleNode right_minus = leaf(2, 1);
  right_minus.timing.align_right = -1;
  ScheduleNode right_plus = leaf(3, 2);
  right_plus.timing.align_right = 2;
  const auto s = schedule(group(Kind::parallel, {leaf(0, 5), right0, right_minus, right_plus}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 5}, {1, 4, 5}, {2, 3, 4}, {3, 5, 7}}));
  EXPECT_EQ(s->end, 7);  // a right-aligned child with positive padding outlasts the rest
}

TEST(Schedule, RightAlignmentInASequenceIsAnError) {
  ScheduleNode right = leaf(1, 1);
  right.timing.align_right = 0;
  const auto s = schedule(group(Kind::sequence, {leaf(0, 1), right}));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().where.line, 2);
  EXPECT_EQ(s.error().message, "right alignment is only allowed in a parallel, not in a sequence");
}

TEST(Schedule, OpenLeafNeedsAnEnd) {
  const auto lonely = schedule(group(Kind::sequence, {leaf(0, {})}));
  ASSERT_FALSE(lonely.ok());
  EXPECT_EQ(lonely.error().where.line, 1);
  const auto bounded = schedule(group(Kind::sequence, {leaf(0, {})}), ScheduleOptions{7.0});
  ASSERT_TRUE(bounded.ok());
  EXPECT_EQ(spans(*bounded), (Spans{{0, 0, 7}}));
}

TEST(Schedule, RepeatsAreCutAtTheActiveEnd) {
  ScheduleNode repeated = leaf(0, 2);
  repeated.timing.repeat = 2.5;
  const auto s = schedule(group(Kind::sequence, {repeated, leaf(1, 1)}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 2}, {0, 2, 4}, {0, 4, 5}, {1, 5, 6}}));
  EXPECT_EQ(s->occurrences[2].iteration, 2);
}

TEST(Schedule, RepeatedGroupsRepeatTheirChildren) {
  Timing twice;
  twice.repeat = 2;
  const auto s = schedule(group(Kind::sequence, {group(Kind::sequence, {leaf(0, 1), leaf(1, 2)}, twice)}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 1}, {1, 1, 3}, {0, 3, 4}, {1, 4, 6}}));
}

TEST(Schedule, IndefiniteRepeatFillsTheParentsDuration) {
  ScheduleNode forever = leaf(0, 2);
  forever.timing.repeat_indefinite = true;
  Timing five;
  five.duration = 5;
  const auto s = schedule(group(Kind::parallel, {forever}, five));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 2}, {0, 2, 4}, {0, 4, 5}}));
}

TEST(Schedule, AGroupRepeatingIndefinitelyWithNothingToEndItIsAnError) {
  // Found by the FML reader's tests: this used to lay out iterations forever.
  Timing forever;
  forever.repeat_indefinite = true;
  const auto s = schedule(group(Kind::sequence, {group(Kind::sequence, {leaf(0, 1)}, forever)}));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().where.line, 100);
  EXPECT_EQ(s.error().message, "repeats indefinitely and nothing around it ends: give it or a parent an end");
}

TEST(Schedule, MoreRunsThanTheLimitIsAnErrorAtTheRepeatingNode) {
  // A 1 s iteration repeated beside a 100 s sibling: 100 runs, over a limit of 10.
  Timing forever;
  forever.repeat_indefinite = true;
  ScheduleOptions options;
  options.max_runs = 10;
  const auto s = schedule(group(Kind::parallel, {leaf(0, 100), group(Kind::sequence, {leaf(1, 1)}, forever)}), options);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().where.line, 100);
  EXPECT_EQ(s.error().message, "repeats to too many runs: more than the limit of 10 runs (--max-runs N raises it)");
}

TEST(Schedule, GroupDurationCutsItsChildren) {
  Timing three;
  three.duration = 3;
  const auto s = schedule(group(Kind::sequence, {group(Kind::parallel, {leaf(0, 5)}, three), leaf(1, 1)}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 3}, {1, 3, 4}}));
}

TEST(Schedule, EndWinsOverDuration) {
  ScheduleNode node = leaf(0, 10, 1);
  node.timing.end = 4;
  const auto s = schedule(group(Kind::parallel, {node}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 1, 4}}));
}

TEST(Schedule, ExclusiveChildCutsTheOnePlaying) {
  const auto s = schedule(group(Kind::exclusive, {leaf(0, 5), leaf(1, 5, 2), leaf(2, 1, 9)}));
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(spans(*s), (Spans{{0, 0, 2}, {1, 2, 7}, {2, 9, 10}}));
}

}  // namespace
}  // namespace fapc

namespace fapc {
namespace {

// Worked out by hand from SMIL: an empty par (or an excl whose event picked no branch) lasts 0 s.
// It used to make its sequence's length unknown, and the sequence then repeated itself until the
// run limit ("story repeats to more than 1000000 runs").
TEST(ScheduleEmptyGroups, AnEmptyParallelBesideATimedLeafLastsNothing) {
  const auto s = schedule(group(Kind::sequence, {group(Kind::parallel, {}), leaf(0, 2)}));
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_EQ(spans(*s), (std::vector<std::tuple<std::size_t, double, double>>{{0, 0, 2}}));
  EXPECT_EQ(s->end, 2);
  const auto excl = schedule(group(Kind::sequence, {leaf(0, 1), group(Kind::exclusive, {}), leaf(1, 1)}));
  ASSERT_TRUE(excl.ok()) << excl.error().message;
  EXPECT_EQ(spans(*excl), (std::vector<std::tuple<std::size_t, double, double>>{{0, 0, 1}, {1, 1, 2}}));
}

TEST(ScheduleEmptyGroups, AGroupThatDoesNotRepeatIsLaidOutOnceEvenWhenItsLengthIsOpen) {
  // The parallel's length is known only once its open child is stretched to the 4 s sibling;
  // the sequence around it (no repeat) must not be repeated.
  const auto s = schedule(group(Kind::sequence, {group(Kind::parallel, {leaf(0, 4), leaf(1, {})})}));
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_EQ(spans(*s), (std::vector<std::tuple<std::size_t, double, double>>{{0, 0, 4}, {1, 0, 4}}));
}

}  // namespace
}  // namespace fapc

namespace fapc {
namespace {

// Mimic `left=1e300`: 1e300 + 3 == 1e300, so the run began and ended at once and the action
// vanished from the output without a word.
TEST(ScheduleHostileTimes, AnActionEndingBeyondTheLatestTimeIsAnErrorAtTheAction) {
  const auto s = schedule(group(Kind::sequence, {leaf(0, 3, 1e300)}));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().where.line, 1);
  EXPECT_EQ(s.error().message, "the action ends at 1e+300 s, after the latest time fapc schedules (2e+09 s)");
  EXPECT_TRUE(schedule(group(Kind::sequence, {leaf(0, 3, 1e6)})).ok());
}

}  // namespace
}  // namespace fapc

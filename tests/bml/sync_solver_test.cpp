// The BML scheduler's constraint solving (xmt/bml/src/bml/sync_solver.hpp) on its own: chains of
// references, contradictions named with their chain, order and block errors, after/before, and
// time linear in the behaviours.
#include <gtest/gtest.h>

#include <chrono>

#include "bml/sync_solver.hpp"

namespace fapc::bml {
namespace {

SolverBehaviour flexible(double length = 1.0) {
  SolverBehaviour b;
  b.defaults = {0, 0.1 * length, 0.2 * length, 0.5 * length, 0.8 * length, 0.9 * length, length};
  return b;
}

Relation equal(std::uint32_t a, std::uint32_t pa, std::optional<PointRef> b, double offset, int label) {
  Relation r;
  r.a = {a, pa};
  r.b = b;
  r.offset = offset;
  r.label = label;
  return r;
}

TEST(SyncSolver, UnconstrainedBehavioursStartAtTheBlockStartWithTheirDefaults) {
  const Solved s = solve({flexible(1), flexible(2)}, {});
  ASSERT_FALSE(s.error);
  EXPECT_DOUBLE_EQ(s.solution.points[0][kStart], 0);
  EXPECT_DOUBLE_EQ(s.solution.points[0][kEnd], 1);
  EXPECT_DOUBLE_EQ(s.solution.points[1][kStroke], 1);
}

// OpenBMLParser's testoffsetchain.xml: h1 = h2 - 2 = h3 - 4 = h4 - 6, h4 at 10, written last.
TEST(SyncSolver, AChainOfOffsetsWrittenBackwardsResolves) {
  std::vector<Relation> r = {equal(0, kStart, PointRef{1, kStart}, -2, 0), equal(1, kStart, PointRef{2, kStart}, -2, 1),
                             equal(2, kStart, PointRef{3, kStart}, -2, 2), equal(3, kStart, std::nullopt, 10, 3)};
  const Solved s = solve({flexible(), flexible(), flexible(), flexible()}, r);
  ASSERT_FALSE(s.error);
  EXPECT_DOUBLE_EQ(s.solution.points[0][kStart], 4);
  EXPECT_DOUBLE_EQ(s.solution.points[1][kStart], 6);
  EXPECT_DOUBLE_EQ(s.solution.points[2][kStart], 8);
  EXPECT_DOUBLE_EQ(s.solution.points[3][kStart], 10);
}

TEST(SyncSolver, TwoFixedPointsStretchTheBehaviourBetweenThem) {
  // testgazereadytimed.xml: ready at 3, end at 10.
  const Solved s = solve({flexible()}, {equal(0, kReady, std::nullopt, 3, 0), equal(0, kEnd, std::nullopt, 10, 1)});
  ASSERT_FALSE(s.error);
  EXPECT_DOUBLE_EQ(s.solution.points[0][kReady], 3);
  EXPECT_DOUBLE_EQ(s.solution.points[0][kEnd], 10);
  EXPECT_DOUBLE_EQ(s.solution.points[0][kStart], 3 - 0.1);  // before the first fixed point: its default
  // Between ready (0.1) and end (1.0), stroke (0.5) is 4/9 of the way.
  EXPECT_NEAR(s.solution.points[0][kStroke], 3 + 7.0 * 4 / 9, 1e-9);
}

TEST(SyncSolver, AContradictionIsNamedAtTheConstraintThatCannotHoldWithItsChain) {
  // a:start = b:start + 1, b:start = c:start + 1, then c:start = a:start (a cycle of sum 2).
  std::vector<Relation> r = {equal(0, kStart, PointRef{1, kStart}, 1, 10), equal(1, kStart, PointRef{2, kStart}, 1, 11),
                             equal(2, kStart, PointRef{0, kStart}, 0, 12)};
  const Solved s = solve({flexible(), flexible(), flexible()}, r);
  ASSERT_TRUE(s.error);
  EXPECT_EQ(s.error->what, SolveError::What::contradiction);
  EXPECT_EQ(s.error->label, 12);
  EXPECT_EQ(s.error->chain, (std::vector<int>{10, 11}));
  EXPECT_DOUBLE_EQ(s.error->time, 0);
  EXPECT_DOUBLE_EQ(s.error->other_time, -2);
}

TEST(SyncSolver, AConsistentCycleIsNoError) {
  std::vector<Relation> r = {equal(0, kStart, PointRef{1, kStart}, 0, 0), equal(1, kStart, PointRef{0, kStart}, 0, 1)};
  EXPECT_FALSE(solve({flexible(), flexible()}, r).error);
}

TEST(SyncSolver, AnEndBeforeItsStartIsAnOrderError) {
  // testnod_invalidtime.xml: start 2, end 0.
  const Solved s = solve({flexible()}, {equal(0, kStart, std::nullopt, 2, 0), equal(0, kEnd, std::nullopt, 0, 1)});
  ASSERT_TRUE(s.error);
  EXPECT_EQ(s.error->what, SolveError::What::order);
  EXPECT_EQ(s.error->label, 1);
  EXPECT_EQ(s.error->chain, std::vector<int>{0});
}

TEST(SyncSolver, ARigidBehaviourEndedTooEarlyWouldStartBeforeItsBlock) {
  // testspeech_endtimed2.xml: a speech of 2 s told to end at 0.1 s.
  SolverBehaviour speech;
  speech.rigid = true;
  speech.defaults = {0, 0, 0, 0, 2, 2, 2};
  speech.own_label = 7;
  const Solved s = solve({speech}, {equal(0, kEnd, std::nullopt, 0.1, 8)});
  ASSERT_TRUE(s.error);
  EXPECT_EQ(s.error->what, SolveError::What::before_block);
  EXPECT_EQ(s.error->label, 8);
  EXPECT_NEAR(s.error->time, -1.9, 1e-9);
}

TEST(SyncSolver, ARigidBehaviourContradictedByTwoTimesNamesItsOwnLength) {
  // testspeech_invalidtime.xml: start 2 and end 0 of a rigid speech.
  SolverBehaviour speech;
  speech.rigid = true;
  speech.defaults = {0, 0, 0, 0, 1, 1, 1};
  speech.own_label = 0;
  const Solved s = solve({speech}, {equal(0, kStart, std::nullopt, 2, 1), equal(0, kEnd, std::nullopt, 0, 2)});
  ASSERT_TRUE(s.error);
  EXPECT_EQ(s.error->what, SolveError::What::contradiction);
  EXPECT_EQ(s.error->label, 2);
  EXPECT_EQ(s.error->chain, (std::vector<int>{1, 0}));
}

TEST(SyncSolver, AfterMovesTheFreeBehaviourLater) {
  SolverBehaviour speech;
  speech.rigid = true;
  speech.defaults = {0, 0, 0, 0, 3, 3, 3};
  speech.marks = {1.5};
  Relation after;
  after.kind = Relation::Kind::at_least;
  after.a = {1, kStroke};
  after.b = PointRef{0, kStandardPoints};
  after.offset = 0;
  const Solved s = solve({speech, flexible()}, {after});
  ASSERT_FALSE(s.error);
  EXPECT_NEAR(s.solution.points[1][kStroke], 1.5, 1e-9);
  EXPECT_NEAR(s.solution.marks[0][0], 1.5, 1e-9);
}

TEST(SyncSolver, AnAfterBetweenFixedTimesThatFailsIsUnmet) {
  Relation after;
  after.kind = Relation::Kind::at_least;
  after.a = {1, kStart};
  after.b = PointRef{0, kStart};
  after.label = 3;
  const Solved s = solve({flexible(), flexible()},
                         {equal(0, kStart, std::nullopt, 5, 1), equal(1, kStart, std::nullopt, 2, 2), after});
  ASSERT_TRUE(s.error);
  EXPECT_EQ(s.error->what, SolveError::What::unmet);
  EXPECT_EQ(s.error->label, 3);
}

// Each behaviour starts at the previous one's end: 10^5 and 4 x 10^5 behaviours, time about
// proportional (a quadratic solver would take 16 times as long).
double chain_seconds(std::uint32_t n) {
  std::vector<SolverBehaviour> behaviours(n, flexible());
  std::vector<Relation> relations;
  relations.reserve(n);
  for (std::uint32_t i = 1; i < n; ++i)
    relations.push_back(equal(i, kStart, PointRef{i - 1, kEnd}, 0, static_cast<int>(i)));
  const auto t0 = std::chrono::steady_clock::now();
  const Solved s = solve(behaviours, relations);
  const auto t1 = std::chrono::steady_clock::now();
  EXPECT_FALSE(s.error);
  EXPECT_NEAR(s.solution.points[n - 1][kEnd], n * 1.0, 1e-6 * n);
  return std::chrono::duration<double>(t1 - t0).count();
}

TEST(SyncSolver, AChainIsSolvedInLinearTime) {
  const double small = chain_seconds(100'000);
  const double large = chain_seconds(400'000);
  std::printf("chain of 1e5: %.3f s, 4e5: %.3f s\n", small, large);
  EXPECT_LT(large, 8 * small + 0.05);
}

}  // namespace
}  // namespace fapc::bml

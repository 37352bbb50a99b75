// Properties of the scheduler over random trees: time is homogeneous (shifting the root shifts
// everything) and scale-free (stretching every duration and offset stretches every occurrence),
// and every occurrence lies inside its run.
#include <gtest/gtest.h>

#include <random>

#include "fapc/timeline/schedule.hpp"

namespace fapc {
namespace {

using Kind = ScheduleNode::Kind;

class RandomTree {
 public:
  explicit RandomTree(unsigned seed) : rng_(seed) {}

  ScheduleNode make(int depth, bool in_parallel) {
    Timing timing;
    timing.offset = pick(0, 3);
    if (depth == 0 || coin(0.4)) {
      // Open leaves only where a parallel can end them.
      if (!in_parallel || coin(0.8)) timing.duration = pick(0.5, 4);
      if (timing.duration && coin(0.2)) timing.repeat = pick(1, 3);
      if (in_parallel && timing.duration && coin(0.15)) timing.align_right = pick(-1, 1);
      return ScheduleNode::leaf(next_leaf_++, timing, Location{});
    }
    const Kind kind = coin(0.5) ? Kind::sequence : (coin(0.8) ? Kind::parallel : Kind::exclusive);
    if (coin(0.15)) timing.repeat = 2;
    ScheduleNode node = ScheduleNode::group(kind, timing, Location{});
    const int children = 1 + static_cast<int>(rng_() % 4);
    for (int i = 0; i < children; ++i) node.children.push_back(make(depth - 1, kind != Kind::sequence));
    // A sequence of open children has no end; give the first child a length.
    return node;
  }

 private:
  std::mt19937 rng_;
  std::size_t next_leaf_ = 0;

  bool coin(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  // Quarter steps, so scaled and shifted times stay exact in binary.
  double pick(double low, double high) {
    const auto steps = static_cast<int>((high - low) * 4);
    return low + static_cast<double>(rng_() % static_cast<unsigned>(steps + 1)) / 4;
  }
};

void scale(ScheduleNode& node, double factor) {
  Timing& t = node.timing;
  t.offset *= factor;
  if (t.duration) *t.duration *= factor;
  if (t.end) *t.end *= factor;
  if (t.align_right) *t.align_right *= factor;
  for (ScheduleNode& child : node.children) scale(child, factor);
}

TEST(ScheduleProperties, ShiftingAndStretchingCommuteWithScheduling) {
  int scheduled = 0;
  for (unsigned seed = 1; seed <= 300; ++seed) {
    ScheduleNode root = RandomTree(seed).make(4, false);
    const ScheduleOptions bounded{40.0};
    const auto base = schedule(root, bounded);
    if (!base.ok()) continue;  // e.g. open leaves with nothing to end them
    ++scheduled;
    for (const Occurrence& o : base->occurrences) {
      ASSERT_LE(o.begin, o.end) << "seed " << seed;
      ASSERT_LE(o.end, o.begin + o.simple_duration) << "seed " << seed;
    }

    ScheduleNode shifted = root;
    shifted.timing.offset += 5;
    const auto moved = schedule(shifted, ScheduleOptions{45.0});
    ASSERT_TRUE(moved.ok()) << "seed " << seed;
    ASSERT_EQ(moved->occurrences.size(), base->occurrences.size()) << "seed " << seed;
    for (std::size_t i = 0; i < base->occurrences.size(); ++i) {
      ASSERT_EQ(moved->occurrences[i].leaf_id, base->occurrences[i].leaf_id);
      ASSERT_DOUBLE_EQ(moved->occurrences[i].begin, base->occurrences[i].begin + 5) << "seed " << seed;
      ASSERT_DOUBLE_EQ(moved->occurrences[i].end, base->occurrences[i].end + 5) << "seed " << seed;
    }

    ScheduleNode stretched = root;
    scale(stretched, 2);
    const auto wide = schedule(stretched, ScheduleOptions{80.0});
    ASSERT_TRUE(wide.ok()) << "seed " << seed;
    ASSERT_EQ(wide->occurrences.size(), base->occurrences.size()) << "seed " << seed;
    for (std::size_t i = 0; i < base->occurrences.size(); ++i) {
      ASSERT_DOUBLE_EQ(wide->occurrences[i].begin, 2 * base->occurrences[i].begin) << "seed " << seed;
      ASSERT_DOUBLE_EQ(wide->occurrences[i].end, 2 * base->occurrences[i].end) << "seed " << seed;
    }
  }
  EXPECT_GT(scheduled, 150);  // most random trees are valid; the properties were really checked
}

}  // namespace
}  // namespace fapc

// The operators on animations (Algebra definitions 4 to 6, docs/algebra.md), with frames worked out
// by hand.
#include <gtest/gtest.h>

#include "fapc/transcoder/algebra.hpp"

namespace fapc::algebra {
namespace {

// An animation of open_jaw values, one per frame; nullopt: the frame is missing.
Animation jaw(int fps, std::initializer_list<std::optional<int>> values) {
  Animation a;
  a.fps = fps;
  for (const auto& v : values) {
    if (!v) {
      a.frames.emplace_back();
      continue;
    }
    FacialState s;
    s.at(3) = *v;
    a.frames.push_back(s);
  }
  a.carried.set(0);
  return a;
}

std::vector<std::optional<int>> jaw_values(const Animation& a) {
  std::vector<std::optional<int>> out;
  for (const auto& f : a.frames) out.push_back(f ? std::optional<int>(f->at(3)) : std::nullopt);
  return out;
}
using Values = std::vector<std::optional<int>>;

TEST(AlgebraAnimation, SumIsFrameByFrameAndSingleFramesPassThrough) {
  // Algebra definition 6: both -> D +_v E; one -> that one (unweighted); neither -> neutral.
  const Animation a = jaw(25, {10, 20, std::nullopt, 40});
  const Animation b = jaw(25, {30, std::nullopt, std::nullopt, 0, 7});
  EXPECT_EQ(jaw_values(sum(a, b, 0.5)), (Values{20, 20, 0, 20, 7}));
}

TEST(AlgebraAnimation, DisjointAnimationsJoinWithNeutralFrames) {
  // Algebra definition 5: B delayed by 4 frames (0.16 s at 25 fps) after A's 2 frames: two neutral
  // frames.
  const Animation a = jaw(25, {10, 20});
  const Animation b = shifted(jaw(25, {30, 40}), 0.16);
  const Result<Animation> joined = overlap({{a, Mask::all(), 1}, {b, Mask::all(), 2}});
  ASSERT_TRUE(joined.ok());
  EXPECT_EQ(jaw_values(*joined), (Values{10, 20, 0, 0, 30, 40}));
}

TEST(AlgebraAnimation, DifferentRatesMeetOnTheHigherOne) {
  // A at 10 fps (0, 100) resampled to 20 fps: 0, 50, 100, 100 (the last frame holds its slot).
  const Animation a = jaw(10, {0, 100});
  const Animation r = resample(a, 20);
  EXPECT_EQ(jaw_values(r), (Values{0, 50, 100, 100}));
  const Animation b = jaw(20, {10, 10, 10, 10});
  const Animation s = sum(a, b, 0.5);
  EXPECT_EQ(s.fps, 20);
  EXPECT_EQ(jaw_values(s), (Values{5, 30, 55, 55}));
}

TEST(AlgebraAnimation, AmplifierScalesEveryFrame) {
  EXPECT_EQ(jaw_values(amplify(jaw(25, {3, std::nullopt, -5}), 0.5)), (Values{2, std::nullopt, -3}));
}

TEST(AlgebraAnimation, FramesRoundTripThroughFapSequences) {
  FapSequence seq;
  seq.fps = 25;
  FapFrame f0;
  f0.number = 0;
  f0.set(3, 10);
  f0.set(48, -20);
  FapFrame f2 = f0;
  f2.number = 2;
  seq.frames = {f0, f2};
  const Animation a = animation_from(seq);
  EXPECT_EQ(a.size(), 3u);
  EXPECT_FALSE(a.frames[1].has_value());
  const FapSequence back = sequence_from(a, "x");
  ASSERT_EQ(back.frames.size(), 2u);
  EXPECT_TRUE(back.frames[1].same_content(f2));
  EXPECT_EQ(back.frames[1].number, 2);
}

}  // namespace
}  // namespace fapc::algebra

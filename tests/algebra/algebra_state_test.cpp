// The paper's definitions on facial states, with vectors computed by hand.
#include <gtest/gtest.h>

#include "fapc/transcoder/algebra.hpp"

namespace fapc::algebra {
namespace {

FacialState state(std::initializer_list<std::pair<int, std::int32_t>> values) {
  FacialState s;
  for (const auto& [fap, v] : values) s.at(fap) = v;
  return s;
}

TEST(AlgebraState, RoundingIsHalfAwayFromZero) {
  EXPECT_EQ(round_half_away(2.5), 3);
  EXPECT_EQ(round_half_away(-2.5), -3);
  EXPECT_EQ(round_half_away(2.49), 2);
  EXPECT_EQ(round_half_away(-0.5), -1);
}

TEST(AlgebraState, SumWeighsEachOperandAndRoundsEachProduct) {
  // (1): round(s v) + round(t (1 - v)). v = 0.3: open_jaw 100, 50 -> 30 + 35 = 65;
  // head_pitch 5, 5 -> round(1.5) + round(3.5) = 2 + 4 = 6 (rounding each product, not the sum).
  const FacialState s = state({{3, 100}, {48, 5}});
  const FacialState t = state({{3, 50}, {48, 5}});
  const FacialState r = sum(s, t, 0.3);
  EXPECT_EQ(r.at(3), 65);
  EXPECT_EQ(r.at(48), 6);
  EXPECT_EQ(sum(s, t, 0.5).at(3), 75);  // v = 1/2: the mean
}

TEST(AlgebraState, AmplifierIsTheSumWithTheNeutralState) {
  // (2): round(w s); and S +_w N = w S.
  const FacialState s = state({{3, 101}, {19, -7}, {48, 3}});
  const FacialState a = amplify(s, 0.5);
  EXPECT_EQ(a.at(3), 51);   // 50.5 -> 51
  EXPECT_EQ(a.at(19), -4);  // -3.5 -> -4
  EXPECT_EQ(a.at(48), 2);   // 1.5 -> 2
  EXPECT_EQ(sum(s, FacialState{}, 0.5), a);
  EXPECT_EQ(amplify(s, 1), s);
}

TEST(AlgebraState, OverlapperTakesTheNonZeroOrTheHigherPriority) {
  // (3): mouth from the smile (priority 2), brows from the anger (priority 1); where both are
  // non-zero on a FAP both masks cover, the higher priority wins.
  const FacialState smile = state({{12, 150}, {13, 150}, {31, 20}});
  const FacialState anger = state({{12, -40}, {31, -90}, {32, -90}});
  Mask mouth_and_brow31;
  for (const int f : {12, 13, 31}) mouth_and_brow31.set(f);
  const Result<Layer> r = overlap(Layer::of(smile, mouth_and_brow31, 2), Layer::of(anger, Mask::all(), 1));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->state.at(12), 150);  // both non-zero: priority 2
  EXPECT_EQ(r->state.at(13), 150);  // only the smile
  EXPECT_EQ(r->state.at(31), 20);   // both non-zero: priority 2
  EXPECT_EQ(r->state.at(32), -90);  // only the anger
  const Result<Layer> tie = overlap(Layer::of(smile, Mask::all(), 1), Layer::of(anger, Mask::all(), 1));
  ASSERT_FALSE(tie.ok());
  EXPECT_EQ(tie.error().message,
            "equal priorities (1) overlap on raise_l_cornerlip: give the operands different priorities");
}

TEST(AlgebraState, MasksByGroupsNamesNumbersAndRanges) {
  const Result<Mask> mouth = parse_mask("mouth");
  ASSERT_TRUE(mouth.ok());
  EXPECT_TRUE(mouth->covers(3));
  EXPECT_TRUE(mouth->covers(60));
  EXPECT_FALSE(mouth->covers(31));
  EXPECT_EQ(mouth->bits.count(), 26u);  // 3-18 and 51-60
  const Result<Mask> mixed = parse_mask("brows, head_yaw,19-20");
  ASSERT_TRUE(mixed.ok());
  EXPECT_EQ(mixed->bits.count(), 8u + 1u + 2u);
  const Result<Mask> most = parse_mask("all,!head");
  ASSERT_TRUE(most.ok());
  EXPECT_EQ(most->bits.count(), 63u);
  const Result<Mask> bad = parse_mask("brows,eyez");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().where.column, 6);  // 0-based offset of "eyez"
  EXPECT_FALSE(parse_mask("1-2").ok());
  EXPECT_FALSE(parse_mask("viseme").ok());
}

TEST(AlgebraState, StatesFromExpressionEntriesGoThroughTheProfile) {
  // jaw -> open_jaw x 1024 (default profile): 0.1 -> 102.4 -> 102; lookat_x drives both eyes.
  const std::vector<ExpressionEntry> entries{{"jaw", 0.1, {}}, {"lookat_x", 1, {}}, {"fap48", -3.5, {}}};
  const Result<FacialState> s = state_from_entries(entries, default_profile());
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->at(3), 102);
  EXPECT_EQ(s->at(23), 524);  // 523.599
  EXPECT_EQ(s->at(24), 524);
  EXPECT_EQ(s->at(48), -4);
  EXPECT_FALSE(state_from_entries({{"smyle", 1, {}}}, default_profile()).ok());
}

}  // namespace
}  // namespace fapc::algebra

// The properties the paper states, over random states; where rounding breaks one, the test
// measures by how much (the figures are in docs/algebra.md) instead of trusting the paper.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>

#include "fapc/codec/fap_table.hpp"
#include "fapc/transcoder/algebra.hpp"

namespace fapc::algebra {
namespace {

class Random {
 public:
  explicit Random(unsigned seed) : rng_(seed) {}

  // Within each FAP's legal range, about a third of the FAPs zero (as in real expressions).
  FacialState state() {
    FacialState s;
    for (int fap = 3; fap <= 68; ++fap) {
      if (pick(0, 2) == 0) continue;
      const int limit = find_fap(fap)->legal_max();
      s.at(fap) = pick(-limit, limit);
    }
    return s;
  }
  Mask mask() {
    Mask m;
    for (int fap = 3; fap <= 68; ++fap) {
      if (pick(0, 1)) m.set(fap);
    }
    return m;
  }
  double unit() { return std::uniform_real_distribution<double>(0, 1)(rng_); }
  int pick(int low, int high) { return std::uniform_int_distribution<int>(low, high)(rng_); }

 private:
  std::mt19937 rng_;
};

constexpr int kTrials = 2000;

TEST(AlgebraProperties, OverlapperIsCommutativeAndAssociative) {
  Random r(1);
  for (int i = 0; i < kTrials; ++i) {
    const Layer a = Layer::of(r.state(), r.mask(), 1);
    const Layer b = Layer::of(r.state(), r.mask(), 2);
    const Layer c = Layer::of(r.state(), r.mask(), 3);
    const auto ab = overlap(a, b);
    const auto ba = overlap(b, a);
    ASSERT_TRUE(ab.ok() && ba.ok());
    EXPECT_EQ(ab->state, ba->state);
    const auto left = overlap(*ab, c);
    const auto bc = overlap(b, c);
    ASSERT_TRUE(left.ok() && bc.ok());
    const auto right = overlap(a, *bc);
    ASSERT_TRUE(right.ok());
    EXPECT_EQ(left->state, right->state);
  }
}

TEST(AlgebraProperties, NeutralStateIsTheOverlappersIdentity) {
  Random r(2);
  for (int i = 0; i < kTrials; ++i) {
    const Layer a = Layer::of(r.state(), Mask::all(), 1);
    const auto with_neutral = overlap(a, Layer::of(FacialState{}, Mask::all(), 2));
    ASSERT_TRUE(with_neutral.ok());
    EXPECT_EQ(with_neutral->state, a.state);
  }
}

TEST(AlgebraProperties, AmplifierIdentityIsOne) {
  Random r(3);
  for (int i = 0; i < kTrials; ++i) {
    const FacialState s = r.state();
    EXPECT_EQ(amplify(s, 1), s);
  }
}

TEST(AlgebraProperties, SumIsCommutativeWithTheComplementWeight) {
  // The paper's "generalized" commutativity: S +_v T = T +_(1-v) S, exact.
  Random r(4);
  for (int i = 0; i < kTrials; ++i) {
    const FacialState s = r.state();
    const FacialState t = r.state();
    const double v = r.unit();
    EXPECT_EQ(sum(s, t, v), sum(t, s, 1 - v));
  }
}

TEST(AlgebraProperties, AmplifierDistributesOverTheSumUpToRounding) {
  // w (S +_v T) against w S +_v w T: exact without rounding; with it, each side rounds three
  // times: the left side's two inner roundings are scaled by w, so the gap is at most |w| + 2
  // (|w| (1/2 + 1/2) + 1/2 on the left, 1/2 + 1/2 + 1/2 on the right). Measured for w in [0, 2]:
  // at most 3 per FAP (docs/algebra.md). The paper claims equality.
  Random r(5);
  int worst = 0;
  long differing = 0;
  for (int i = 0; i < kTrials; ++i) {
    const FacialState s = r.state();
    const FacialState t = r.state();
    const double v = r.unit();
    const double w = 2 * r.unit();
    const FacialState left = amplify(sum(s, t, v), w);
    const FacialState right = sum(amplify(s, w), amplify(t, w), v);
    for (std::size_t k = 0; k < left.values.size(); ++k) {
      const int gap = std::abs(left.values[k] - right.values[k]);
      worst = std::max(worst, gap);
      differing += gap != 0;
    }
  }
  EXPECT_LE(worst, 4);      // the bound for w <= 2
  EXPECT_GT(differing, 0);  // rounding does break exact distributivity; docs/algebra.md says so
  std::printf("amplifier over sum: worst gap %d, %ld FAP values differ in %d trials\n", worst, differing, kTrials);
  RecordProperty("worst_gap", worst);
  RecordProperty("differing_faps_per_2000_trials", static_cast<int>(differing));
}

TEST(AlgebraProperties, ClosureAndRangeLimits) {
  // Overlaps and amplifiers with |w| <= 1 keep legal states legal. The sum can leave the range
  // by one unit through rounding (5 +_0.5 5 = 3 + 3 = 6): measured, never by more.
  Random r(6);
  int worst_excess = 0;
  for (int i = 0; i < kTrials; ++i) {
    const FacialState s = r.state();
    const FacialState t = r.state();
    const FacialState summed = sum(s, t, r.unit());
    const FacialState scaled = amplify(s, 2 * r.unit() - 1);
    const auto over = overlap(Layer::of(s, r.mask(), 1), Layer::of(t, r.mask(), 2));
    ASSERT_TRUE(over.ok());
    for (int fap = 3; fap <= 68; ++fap) {
      const int limit = find_fap(fap)->legal_max();
      EXPECT_LE(std::abs(scaled.at(fap)), limit);
      EXPECT_LE(std::abs(over->state.at(fap)), limit);
      worst_excess = std::max(worst_excess, std::abs(summed.at(fap)) - limit);
    }
  }
  EXPECT_LE(worst_excess, 1);
  // The smallest case, by hand: legal max 5 would give 6; with real ranges (multiples of 60 times
  // the quantiser step, all even) the halves meet at L/2 each: check the bound directly.
  FacialState edge;
  edge.at(48) = find_fap(48)->legal_max() - 1;                        // odd: 316199
  EXPECT_EQ(sum(edge, edge, 0.5).at(48), find_fap(48)->legal_max());  // 158100 + 158100
}

}  // namespace
}  // namespace fapc::algebra

// The encoder's mask fitting (docs/fba.md 2, "Masks"), case by case. Expected masks and values
// are worked out by hand from the rule: a FAP may be sent as 0 or left out where 0 is within half
// a step of what every player shows of it in this frame and the one before, and of its left/right
// partner in this frame.
#include <gtest/gtest.h>

#include <initializer_list>
#include <utility>

#include "fapc/codec/fba.hpp"

namespace fapc {
namespace {

FapFrame frame(std::int64_t number, std::initializer_list<std::pair<int, std::int32_t>> faps) {
  FapFrame f;
  f.number = number;
  for (const auto& [fap, value] : faps) f.set(fap, value);
  return f;
}

struct Coded {
  std::vector<FapFrame> frames;
  std::size_t intra_planes = 0;
};

Coded round_trip(const FapSequence& input, FbaMaskMode masks) {
  FbaEncodeOptions options;
  options.masks = masks;
  auto encoded = encode_fba(input, options);
  EXPECT_TRUE(encoded.ok()) << format_diagnostic(encoded.error());
  if (!encoded.ok()) return {};
  const Status verified = verify_fba(input, *encoded, options);
  EXPECT_TRUE(verified.ok()) << format_diagnostic(verified.error());
  auto decoded = decode_fba(encoded->bytes);
  EXPECT_TRUE(decoded.ok());
  if (!decoded.ok()) return {};
  return {decoded->sequence.frames, decoded->info.intra_planes.size()};
}

// The Xface emotion files' blink: the eyelids (FAPs 19, 20) enter the mask at 0, close, open and
// leave it at 0. Kept masks need an intra plane where they enter and another where they leave;
// fitted, they are sent as 0 around the blink and the stream has one intra plane.
TEST(FbaMaskFitting, AnEyelidBlinkNeedsNoIntraPlanes) {
  FapSequence input;
  const std::int32_t blink[] = {0, 512, 1024, 512, 0};
  for (int k = 0; k < 12; ++k) {
    FapFrame f = frame(k, {{3, 40 + 4 * k}});
    if (k >= 4 && k < 9) {
      f.set(19, blink[k - 4]);
      f.set(20, blink[k - 4]);
    }
    input.frames.push_back(f);
  }
  const Coded kept = round_trip(input, FbaMaskMode::keep);
  EXPECT_EQ(kept.intra_planes, 3u);
  const Coded fitted = round_trip(input, FbaMaskMode::fit);
  EXPECT_EQ(fitted.intra_planes, 1u);
  ASSERT_EQ(fitted.frames.size(), 12u);
  for (int k = 0; k < 12; ++k) {
    const FapFrame& f = fitted.frames[static_cast<std::size_t>(k)];
    ASSERT_TRUE(f.has(19) && f.has(20)) << k;
    const std::int32_t want = k >= 4 && k < 9 ? blink[k - 4] : 0;
    EXPECT_EQ(f.value(19), want) << k;
    EXPECT_EQ(f.value(20), want) << k;
    EXPECT_EQ(f.value(3), 40 + 4 * k) << k;  // QP 4: every value is a multiple of the step
  }
}

// FAPs 31 and 32 (QP 2, tolerance 1) never leave rest: they are left out. FAP 19 is 0 too, but its
// partner 20 is not, and the reference decoder would copy 20 into an absent 19: 19 stays.
TEST(FbaMaskFitting, FapsAtRestAreLeftOutUnlessTheirPartnerMoves) {
  FapSequence input;
  for (int k = 0; k < 6; ++k)
    input.frames.push_back(frame(k, {{3, 400}, {19, 0}, {20, 300 + k}, {31, k % 3 - 1}, {32, 0}}));
  const Coded fitted = round_trip(input, FbaMaskMode::fit);
  ASSERT_EQ(fitted.frames.size(), 6u);
  for (const FapFrame& f : fitted.frames) {
    EXPECT_FALSE(f.has(31));
    EXPECT_FALSE(f.has(32));
    EXPECT_TRUE(f.has(19));
    EXPECT_EQ(f.value(19), 0);
  }
  EXPECT_EQ(fitted.intra_planes, 1u);
}

// A FAP that leaves the mask while away from rest keeps its value for a player that holds values
// and drops to 0 for one that does not: that mask change stands. One that leaves at 0 after
// coming back from 400 is sent as 0 instead (a holding player would show 0, as would any other).
TEST(FbaMaskFitting, OnlyChangesAtRestAreFitted) {
  FapSequence away;
  for (int k = 0; k < 6; ++k) away.frames.push_back(k < 3 ? frame(k, {{3, 400}, {4, 10}}) : frame(k, {{4, 10}}));
  const Coded kept = round_trip(away, FbaMaskMode::fit);
  EXPECT_EQ(kept.intra_planes, 2u);
  ASSERT_EQ(kept.frames.size(), 6u);
  EXPECT_TRUE(kept.frames[2].has(3));
  EXPECT_FALSE(kept.frames[3].has(3));

  FapSequence back;
  for (int k = 0; k < 6; ++k)
    back.frames.push_back(k < 3 ? frame(k, {{3, k == 0 ? 400 : 0}, {4, 10}}) : frame(k, {{4, 10}}));
  const Coded filled = round_trip(back, FbaMaskMode::fit);
  EXPECT_EQ(filled.intra_planes, 1u);
  ASSERT_EQ(filled.frames.size(), 6u);
  for (std::size_t k = 1; k < 6; ++k) {
    ASSERT_TRUE(filled.frames[k].has(3)) << k;
    EXPECT_EQ(filled.frames[k].value(3), 0) << k;
  }
}

// verify_fba compares what players show, not masks: a stream that shows FAP 3 at 0 where the
// input leaves it out after 100 fails for the player that holds values.
TEST(FbaMaskFitting, VerificationNamesThePlayerThatWouldSeeADifference) {
  FapSequence sent, claimed;
  sent.frames = {frame(0, {{3, 100}}), frame(1, {{3, 0}})};
  claimed.frames = {frame(0, {{3, 100}}), frame(1, {})};
  auto encoded = encode_fba(sent);
  ASSERT_TRUE(encoded.ok());
  const Status verified = verify_fba(claimed, *encoded, FbaEncodeOptions{});
  ASSERT_FALSE(verified.ok());
  EXPECT_NE(verified.error().message.find("frame 1: FAP 3 (open_jaw) decoded 0, encoded 100"), std::string::npos)
      << verified.error().message;
  EXPECT_NE(verified.error().message.find("a player that holds absent FAPs"), std::string::npos);
}

}  // namespace
}  // namespace fapc

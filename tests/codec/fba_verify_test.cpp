// verify_fba takes its input whole or a frame at a time (the streamed conversions' --verify); one
// implementation decodes the stream twice, frame by frame. What it reports, and in which order:
// a count that differs before any frame's difference, the rate next, then the first frame that
// differs. The expected texts are written from docs/fba.md's account of the checks.
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

FapSequence sequence(int fps, std::vector<FapFrame> frames) {
  FapSequence s;
  s.fps = fps;
  s.frames = std::move(frames);
  return s;
}

std::string message_of(const Status& status) { return status ? std::string() : status.error().message; }

const FapSequence kSent = sequence(25, {frame(0, {{3, 100}}), frame(1, {{3, 200}}), frame(2, {{3, 300}})});

TEST(FbaVerify, AcceptsTheFramesItEncoded) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  EXPECT_TRUE(verify_fba(kSent, *encoded, FbaEncodeOptions{}).ok());
}

TEST(FbaVerify, ReportsADifferentCountBeforeAnyFrameThatDiffers) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  const FapSequence shorter = sequence(25, {frame(0, {{3, 900}}), frame(1, {{3, 200}})});
  EXPECT_EQ(message_of(verify_fba(shorter, *encoded, FbaEncodeOptions{}, "x.fba")),
            "verification failed: 3 frames decoded, 2 encoded");
}

TEST(FbaVerify, ReportsTheRateBeforeAnyFrameThatDiffers) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  const FapSequence other_rate = sequence(30, {frame(0, {{3, 900}}), frame(1, {{3, 200}}), frame(2, {{3, 300}})});
  EXPECT_EQ(message_of(verify_fba(other_rate, *encoded, FbaEncodeOptions{})),
            "verification failed: frame rate 25 decoded, 30 encoded");
}

TEST(FbaVerify, ReportsTheFirstFrameThatDiffers) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  const FapSequence later = sequence(25, {frame(0, {{3, 100}}), frame(1, {{3, 250}}), frame(2, {{3, 900}})});
  // FAP 3's step at fap_quant 1 is its QP, 4: a tolerance of 2.
  EXPECT_EQ(message_of(verify_fba(later, *encoded, FbaEncodeOptions{})),
            "verification failed: frame 1: FAP 3 (open_jaw) decoded 200, encoded 250 (tolerance 2, as a player that "
            "shows absent FAPs at 0 shows it)");
}

TEST(FbaVerify, TakesTheInputAFrameAtATimeAndNeverPastItsCount) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  std::size_t asked = 0;
  const auto next = [&]() -> const FapFrame& { return kSent.frames.at(asked++); };
  EXPECT_TRUE(verify_fba(3, 25, next, *encoded, FbaEncodeOptions{}).ok());
  EXPECT_EQ(asked, 3u);
  asked = 0;
  EXPECT_EQ(message_of(verify_fba(2, 25, next, *encoded, FbaEncodeOptions{})),
            "verification failed: 3 frames decoded, 2 encoded");
  EXPECT_LE(asked, 2u);
}

}  // namespace
}  // namespace fapc

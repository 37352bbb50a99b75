// verify_fba takes its input whole or a frame at a time (the streamed conversions' --verify); one
// implementation decodes the stream twice, frame by frame. What it reports, and in which order:
// a count that differs before any frame's difference, the rate next, then the first frame that
// differs. The expected texts are written from docs/fba.md's account of the checks.
#include <gtest/gtest.h>

#include <initializer_list>

#include "fapc/codec/fba.hpp"

namespace fapc {
namespace {

// Frames 0, 1, ... whose FAP 3 (open_jaw) takes these values, at `fps`.
FapSequence jaw(int fps, std::initializer_list<std::int32_t> values) {
  FapSequence s;
  s.fps = fps;
  for (const std::int32_t value : values) {
    FapFrame& f = s.frames.emplace_back();
    f.number = static_cast<std::int64_t>(s.frames.size()) - 1;
    f.set(3, value);
  }
  return s;
}

std::string message_of(const Status& status) { return status ? std::string() : status.error().message; }

const FapSequence kSent = jaw(25, {100, 200, 300});

TEST(FbaVerify, AcceptsTheFramesItEncoded) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  EXPECT_TRUE(verify_fba(kSent, *encoded, FbaEncodeOptions{}).ok());
}

TEST(FbaVerify, ReportsADifferentCountBeforeAnyFrameThatDiffers) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  const FapSequence shorter = jaw(25, {900, 200});
  EXPECT_EQ(message_of(verify_fba(shorter, *encoded, FbaEncodeOptions{}, "x.fba")),
            "verification failed: 3 frames decoded, 2 encoded");
}

TEST(FbaVerify, ReportsTheRateBeforeAnyFrameThatDiffers) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  const FapSequence other_rate = jaw(30, {900, 200, 300});
  EXPECT_EQ(message_of(verify_fba(other_rate, *encoded, FbaEncodeOptions{})),
            "verification failed: frame rate 25 decoded, 30 encoded");
}

TEST(FbaVerify, ReportsTheFirstFrameThatDiffers) {
  const auto encoded = encode_fba(kSent);
  ASSERT_TRUE(encoded.ok());
  const FapSequence later = jaw(25, {100, 250, 900});
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

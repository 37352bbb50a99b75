// The frame limit on FBA streams (docs/security.md, "Resource limits"): the span of a stream, its
// skipped frames included, is checked by the decoder before the frames are kept, and by the
// encoder with the same limit, so fapc never writes a stream it then refuses to read back.
#include <gtest/gtest.h>

#include "fapc/codec/fba.hpp"

namespace fapc {
namespace {

FapSequence frames_at(std::initializer_list<std::int64_t> numbers) {
  FapSequence s;
  s.fps = 25;
  for (const std::int64_t n : numbers) {
    FapFrame f;
    f.number = n;
    f.set(3, static_cast<std::int32_t>(n % 100));
    s.frames.push_back(f);
  }
  return s;
}

TEST(FbaLimits, AStreamThatSkipsMillionsOfFramesIsRefusedByTheDecoder) {
  // Three planes; the second skips 1999999 frames (a few KB of skip codes).
  FbaEncodeOptions encode;
  encode.max_frames = 3000000;
  const auto encoded = encode_fba(frames_at({0, 2000000, 2000001}), encode);
  ASSERT_TRUE(encoded.ok()) << encoded.error().message;
  FbaDecodeOptions decode;
  decode.file = "skips.fba";
  const auto refused = decode_fba(encoded->bytes, decode);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(refused.error().where.file, "skips.fba");
  EXPECT_GT(refused.error().where.byte_offset, 0);
  EXPECT_NE(refused.error().message.find("--max-frames"), std::string::npos) << refused.error().message;
  decode.max_frames = 3000000;
  const auto decoded = decode_fba(encoded->bytes, decode);
  ASSERT_TRUE(decoded.ok()) << decoded.error().message;
  EXPECT_EQ(decoded->sequence.frames.back().number, 2000001);
}

TEST(FbaLimits, TheEncoderRefusesWhatTheDecoderWouldRefuse) {
  FbaEncodeOptions encode;
  encode.max_frames = 1000;
  const auto at_limit = encode_fba(frames_at({0, 999}), encode);
  ASSERT_TRUE(at_limit.ok());
  FbaDecodeOptions decode;
  decode.max_frames = 1000;
  EXPECT_TRUE(decode_fba(at_limit->bytes, decode).ok());
  const auto beyond = encode_fba(frames_at({0, 1000}), encode);
  ASSERT_FALSE(beyond.ok());
  EXPECT_EQ(beyond.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(beyond.error().message,
            "frames 0 to 1000 span 1001 frames: more than the limit of 1000 frames (--max-frames N raises it)");
}

}  // namespace
}  // namespace fapc

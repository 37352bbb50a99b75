// The resource limits on .fap and gzip inputs (docs/security.md, "Resource limits"): small
// inputs that ask for huge allocations are refused before allocating, with the limit and its
// option named; hostile frame numbers are refused before any arithmetic. Inputs are generated
// here, so nothing large is stored.
#include <gtest/gtest.h>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"

namespace fapc {
namespace {

// FAP 3 only.
std::string jaw_mask() {
  std::string out = "0 0 1";
  for (int i = 4; i <= 68; ++i) out += " 0";
  return out;
}

std::string fap_with_numbers(std::initializer_list<const char*> numbers, bool header = true) {
  std::string text = header ? "2.1 t 25 " + std::to_string(numbers.size()) + "\n" : "";
  for (const char* n : numbers) text += jaw_mask() + "\n" + n + " 10\n";
  return text;
}

TEST(FapLimits, FrameNumbersThatJumpFarAreRefusedAtTheFrameThatJumps) {
  // 455 bytes that would be written as 10^8 gap-filled frames (5 GB before the limit).
  const auto read = read_fap_text(fap_with_numbers({"0", "50000000", "100000000"}), "jump.fap");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(format_diagnostic(read.error()),
            "jump.fap:5:1: error: frames 0 to 50000000 span 50000001 frames: more than the limit of "
            "1048576 frames (--max-frames N raises it)");
}

TEST(FapLimits, TheFrameLimitIsTheCallersToRaise) {
  FapReadOptions options;
  options.max_frames = 100000001;
  EXPECT_TRUE(read_fap_text(fap_with_numbers({"0", "50000000", "100000000"}), "jump.fap", options).ok());
  options.max_frames = 3;
  EXPECT_TRUE(read_fap_text(fap_with_numbers({"0", "1", "2"}), "t.fap", options).ok());
  EXPECT_FALSE(read_fap_text(fap_with_numbers({"0", "1", "3"}), "t.fap", options).ok());
}

TEST(FapLimits, MillisecondStampsCountInFramesNotMilliseconds) {
  // No header: 40 ms stamps (25 fps). 40 s of stamps is 1000 frames, far below the limit even
  // though the numbers span 40000.
  FapReadOptions options;
  options.max_frames = 1001;
  EXPECT_TRUE(read_fap_text(fap_with_numbers({"1000", "1040", "41000"}, false), "t.fap", options).ok());
}

TEST(FapLimits, FrameNumbersNearTheEndsOfInt64AreRefusedBeforeArithmetic) {
  // Their difference overflowed std::int64_t (undefined behaviour, caught by UBSan).
  const auto read = read_fap_text(fap_with_numbers({"-9223372036854775800", "9223372036854775800"}), "big.fap");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(format_diagnostic(read.error()),
            "big.fap:3:1: error: frame number -9223372036854775800 is outside "
            "-1000000000000000..1000000000000000");
  const auto high = read_fap_text(fap_with_numbers({"0", "9223372036854775807"}, false), "big.fap");
  ASSERT_FALSE(high.ok());
  EXPECT_EQ(high.error().where.line, 4);
}

TEST(GunzipLimits, ABombIsRefusedAtTheExpansionFactor) {
  // 16 MiB of blanks compress to some 16 KB: a ratio near 1000.
  const std::string bomb = gzip(std::string(std::size_t{16} << 20, ' '));
  ASSERT_LT(bomb.size(), std::size_t{100000});
  const auto out = gunzip(bomb, "bomb.fap.gz");
  ASSERT_FALSE(out.ok());
  EXPECT_EQ(out.error().kind, ErrorKind::limit_exceeded);
  EXPECT_NE(out.error().message.find("--max-expansion"), std::string::npos) << out.error().message;
  EXPECT_GE(out.error().where.byte_offset, 0);
  Limits raised;
  raised.max_expansion = 2000;
  const auto allowed = gunzip(bomb, "bomb.fap.gz", raised);
  ASSERT_TRUE(allowed.ok());
  EXPECT_EQ(allowed->size(), std::size_t{16} << 20);
}

TEST(GunzipLimits, TheAbsoluteLimitHoldsWhateverTheRatio) {
  const std::string data = gzip(std::string(std::size_t{3} << 20, 'x'));
  Limits limits;
  limits.max_expansion = 1e9;
  limits.max_decompressed_bytes = std::int64_t{2} << 20;
  const auto out = gunzip(data, "x.gz", limits);
  ASSERT_FALSE(out.ok());
  EXPECT_EQ(out.error().kind, ErrorKind::limit_exceeded);
  EXPECT_NE(out.error().message.find("--max-decompressed-bytes"), std::string::npos) << out.error().message;
}

TEST(GunzipLimits, SmallRegularFilesPassBelowTheFloor) {
  // 512 KiB of one byte: a ratio far above 100, but below the 1 MiB floor.
  const auto out = gunzip(gzip(std::string(std::size_t{512} << 10, '0')), "small.gz");
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(out->size(), std::size_t{512} << 10);
}

}  // namespace
}  // namespace fapc

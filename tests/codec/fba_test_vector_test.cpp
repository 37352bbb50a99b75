// The three-frame test vector of docs/fba-bitstream.md section 11, reproduced bit for bit. The
// expected bytes and decoded values are copied from that page, where two implementations written
// independently of this one produced them; this code was written without looking at theirs.
#include <gtest/gtest.h>

#include <string>

#include "fapc/codec/fba.hpp"

namespace fapc {
namespace {

FapSequence test_vector_frames() {
  FapSequence sequence;
  sequence.fps = 25;
  struct Row {
    VisemeFields viseme;
    int fap3, fap4, fap5, fap48;
  };
  const Row rows[] = {
      {{10, 3, 40, 0}, 200, -37, 51, 1700},
      {{10, 4, 20, 0}, 230, -30, 40, 2000},
      {{11, 4, 63, 1}, 230, -30, 40, 2000},
  };
  for (int k = 0; k < 3; ++k) {
    FapFrame frame;
    frame.number = k;
    frame.mask.set(0);
    frame.viseme = rows[k].viseme;
    frame.set(3, rows[k].fap3);
    frame.set(4, rows[k].fap4);
    frame.set(5, rows[k].fap5);
    frame.set(48, rows[k].fap48);
    sequence.frames.push_back(frame);
  }
  return sequence;
}

FbaEncodeOptions test_vector_options() {
  FbaEncodeOptions options;
  options.quant = 1;
  options.ranges = FbaRangeMode::max;  // v = 31 for every masked FAP
  options.list_every_mask = true;      // every group with mask type 01
  return options;
}

std::string hex(const std::vector<std::uint8_t>& bytes) {
  static const char* digits = "0123456789ABCDEF";
  std::string out;
  for (const std::uint8_t b : bytes) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

constexpr const char* kExpected =
    "000001BAB19001B5E000A00140285059400A140FFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFF51327C8F177DC1F2"
    "13FDEE7F727B4082FC9399F18008808FF600BF000001B1";

TEST(FbaTestVector, EncodesToThePublishedBytes) {
  auto encoded = encode_fba(test_vector_frames(), test_vector_options());
  ASSERT_TRUE(encoded.ok()) << format_diagnostic(encoded.error());
  EXPECT_EQ(encoded->bytes.size(), 70u);
  EXPECT_EQ(hex(encoded->bytes), kExpected);
  ASSERT_EQ(encoded->planes.size(), 3u);
  EXPECT_TRUE(encoded->planes[0].intra);
  EXPECT_FALSE(encoded->planes[1].intra);
  EXPECT_EQ(encoded->planes[0].bit_offset, 32u);
  EXPECT_EQ(encoded->header_size, 4u);
}

TEST(FbaTestVector, DecodesToThePublishedValues) {
  const auto encoded = encode_fba(test_vector_frames(), test_vector_options());
  ASSERT_TRUE(encoded.ok());
  auto decoded = decode_fba(encoded->bytes);
  ASSERT_TRUE(decoded.ok()) << format_diagnostic(decoded.error());
  const auto& frames = decoded->sequence.frames;
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(decoded->sequence.fps, 25);
  const int expected[3][4] = {{200, -38, 52, 1700}, {232, -30, 40, 2040}, {232, -30, 40, 2040}};
  const int faps[4] = {3, 4, 5, 48};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(frames[k].number, k);
    for (int i = 0; i < 4; ++i)
      EXPECT_EQ(frames[k].value(faps[i]), expected[k][i]) << "frame " << k << " FAP " << faps[i];
    EXPECT_EQ(frames[k].viseme, test_vector_frames().frames[k].viseme) << "frame " << k;
    EXPECT_FALSE(frames[k].has(2));
  }
  EXPECT_TRUE(decoded->warnings.empty());
  EXPECT_EQ(decoded->info.intra_planes.size(), 1u);
  EXPECT_EQ(decoded->info.frames, 3);
}

}  // namespace
}  // namespace fapc

// Where things sit in the bytes: aligned planes are self-contained MP4 samples, the decoder
// configuration is the 14 bytes of docs/mp4-and-xmta.md section 6.2, and a raw stream rebuilt from
// them the way section 6.3 describes decodes to the same frames.
#include <gtest/gtest.h>

#include "fapc/codec/fba.hpp"
#include "fba_sequences.hpp"

namespace fapc {
namespace {

std::vector<std::uint8_t> slice(const std::vector<std::uint8_t>& bytes, std::size_t offset, std::size_t size) {
  return {bytes.begin() + static_cast<long>(offset), bytes.begin() + static_cast<long>(offset + size)};
}

const std::vector<std::uint8_t> kPlaneStartCode{0x00, 0x00, 0x01, 0xBB};
const std::vector<std::uint8_t> kEndCode{0x00, 0x00, 0x01, 0xB1};

TEST(FbaLayout, DecoderSpecificInfoIsTheDocumentedFourteenBytes) {
  const auto dsi = fba_decoder_specific_info();
  // Copied from docs/mp4-and-xmta.md section 6.2, where each field is spelled out.
  const std::array<std::uint8_t, 14> expected{0x00, 0x00, 0x01, 0xB0, 0x63, 0x00, 0x00,
                                              0x01, 0xB5, 0x23, 0x00, 0x00, 0x01, 0xBA};
  EXPECT_EQ(dsi, expected);
}

TEST(FbaLayout, AlignedPlanesAreWholeSamplesThatRebuildTheStream) {
  std::mt19937 rng(3);
  test::SequenceShape shape;
  shape.frames = 60;
  const FapSequence input = test::random_sequence(rng, shape);
  FbaEncodeOptions options;
  options.align_planes = true;
  auto encoded = encode_fba(input, options);
  ASSERT_TRUE(encoded.ok());
  const auto& bytes = encoded->bytes;
  EXPECT_EQ(slice(bytes, 0, 5), (std::vector<std::uint8_t>{0x00, 0x00, 0x01, 0xBA, 0x7F}));
  ASSERT_EQ(encoded->header_size, 5u);
  std::size_t at = encoded->header_size;
  for (const CodedPlane& plane : encoded->planes) {
    EXPECT_EQ(plane.offset, at);
    EXPECT_EQ(plane.bit_offset, 8 * plane.offset);
    EXPECT_EQ(plane.bit_size, 8 * plane.size);
    EXPECT_EQ(slice(bytes, plane.offset, 4), kPlaneStartCode);
    at += plane.size;
  }
  EXPECT_EQ(slice(bytes, at, bytes.size() - at), kEndCode);

  // Decoder configuration, 0x7F, the samples, the end code (docs/mp4-and-xmta.md section 6.3).
  const auto dsi = fba_decoder_specific_info();
  std::vector<std::uint8_t> rebuilt(dsi.begin(), dsi.end());
  rebuilt.push_back(0x7F);
  for (const CodedPlane& plane : encoded->planes) {
    const auto sample = slice(bytes, plane.offset, plane.size);
    rebuilt.insert(rebuilt.end(), sample.begin(), sample.end());
  }
  rebuilt.insert(rebuilt.end(), kEndCode.begin(), kEndCode.end());
  auto decoded = decode_fba(rebuilt);
  ASSERT_TRUE(decoded.ok()) << format_diagnostic(decoded.error());
  EXPECT_EQ(decoded->info.profile_and_level, 0x63);
  EXPECT_TRUE(decoded->info.visual_object_header);
  EXPECT_EQ(decoded->info.plane_start_codes, encoded->planes.size());
  auto direct = decode_fba(bytes);
  ASSERT_TRUE(direct.ok());
  ASSERT_EQ(decoded->sequence.frames.size(), direct->sequence.frames.size());
  for (std::size_t k = 0; k < direct->sequence.frames.size(); ++k) {
    EXPECT_TRUE(decoded->sequence.frames[k].same_content(direct->sequence.frames[k]));
    EXPECT_EQ(decoded->sequence.frames[k].number, direct->sequence.frames[k].number);
  }

  // Without the 0x7F before the first plane start code (the reference decoder needs it, D8).
  rebuilt.erase(rebuilt.begin() + 14);
  auto lenient = decode_fba(rebuilt);
  ASSERT_TRUE(lenient.ok()) << format_diagnostic(lenient.error());
  EXPECT_EQ(lenient->sequence.frames.size(), input.frames.size());
}

TEST(FbaLayout, UnalignedPlanesFollowEachOtherBitForBit) {
  std::mt19937 rng(8);
  const FapSequence input = test::random_sequence(rng, test::SequenceShape{});
  auto encoded = encode_fba(input, FbaEncodeOptions{});
  ASSERT_TRUE(encoded.ok());
  ASSERT_EQ(encoded->header_size, 4u);
  std::size_t bit = 32;
  for (const CodedPlane& plane : encoded->planes) {
    EXPECT_EQ(plane.bit_offset, bit);
    EXPECT_EQ(plane.offset, bit / 8);
    EXPECT_EQ(plane.offset + plane.size, (bit + plane.bit_size + 7) / 8);
    bit += plane.bit_size;
  }
  // Then stuffing (1 to 8 bits) and the end code.
  const std::size_t end = (bit / 8 + 1) * 8;
  EXPECT_EQ(encoded->bytes.size() * 8, end + 32);
}

}  // namespace
}  // namespace fapc

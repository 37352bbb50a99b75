// AAC-LC through libavcodec: the configuration fapc announces is the standard's (worked out by
// hand), and what is encoded decodes back to the same sound at the same times.
#include <gtest/gtest.h>

#include <cmath>

#include "fapc/audio_codec/aac.hpp"
#include "tone.hpp"

namespace fapc::audio {
namespace {

TEST(Aac, AudioSpecificConfigFromTheStandardsSyntax) {
  // 5 bits object type 2, 4 bits frequency index, 4 bits channel configuration 1, 3 zero bits:
  // 22050 Hz is index 7: 00010 0111 0001 000 = 13 88; 44100 Hz index 4: 00010 0100 0001 000 = 12 08;
  // 16000 Hz index 8: 00010 1000 0001 000 = 14 08. Then sync extension 010 1011 0111, object
  // type 00101 (SBR), sbrPresentFlag 0, padding: 0101 0110 | 1110 0101 | 0000 0000 = 0x56 0xE5 0x00.
  EXPECT_EQ(aac_lc_mono_config(22050), (std::vector<std::uint8_t>{0x13, 0x88, 0x56, 0xE5, 0x00}));
  EXPECT_EQ(aac_lc_mono_config(44100), (std::vector<std::uint8_t>{0x12, 0x08, 0x56, 0xE5, 0x00}));
  EXPECT_EQ(aac_lc_mono_config(16000), (std::vector<std::uint8_t>{0x14, 0x08, 0x56, 0xE5, 0x00}));
  EXPECT_TRUE(aac_lc_mono_config(22000).empty());
}

TEST(Aac, EncodedToneDecodesWithItsSilencesInPlace) {
  const AudioTrack tone = test::tone_with_silences(22050);
  auto aac = encode_aac(tone, "t.mp4");
  ASSERT_TRUE(aac.ok()) << format_diagnostic(aac.error());
  EXPECT_EQ(aac->audio_specific_config, aac_lc_mono_config(22050));  // libavcodec agrees
  EXPECT_EQ(aac->length, tone.samples.size());
  EXPECT_GE(aac->frames.size() * kAacFrameLength, aac->priming + aac->length);
  auto back = decode_aac(*aac, "t.mp4");
  ASSERT_TRUE(back.ok()) << format_diagnostic(back.error());
  ASSERT_EQ(back->size(), tone.samples.size());
  // Sound where the tone was, silence where it was not, to within 10 ms (220 samples) of each edge.
  for (const auto& [from, to, loud] : test::tone_segments(22050)) {
    const double rms = test::rms(*back, from + 220, to - 220);
    if (loud)
      EXPECT_GT(rms, 5000.0) << from << ".." << to;
    else
      EXPECT_LT(rms, 100.0) << from << ".." << to;
  }
}

TEST(Aac, RateWithoutAnIndexIsUnsupported) {
  AudioTrack odd = test::tone_with_silences(22050);
  odd.sample_rate = 22000;
  auto aac = encode_aac(odd, "odd.mp4");
  ASSERT_FALSE(aac.ok());
  EXPECT_EQ(aac.error().kind, ErrorKind::unsupported);
  EXPECT_EQ(aac.error().where.file, "odd.mp4");
}

}  // namespace
}  // namespace fapc::audio

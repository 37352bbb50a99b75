// Byte-exact checks of the MP4 writer's descriptors and configurations against the bytes GPAC
// writes for the same content, as recorded (and checked with GPAC) in docs/mp4-and-xmta.md
// section 6.4. Where the project deliberately differs from GPAC (visual profile 0x63 instead of
// GPAC's default 0x01, audio 0xFF instead of 0x00), the test says so.
#include <gtest/gtest.h>

#include "fapc/mpeg4/bifs.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "fapc/mpeg4/object_descriptors.hpp"
#include "fapc/mpeg4/scene.hpp"
#include "test_tracks.hpp"

namespace fapc::xmt {
namespace {

Bytes slice(const Bytes& data, std::uint64_t offset, std::size_t size) {
  return Bytes(data.begin() + static_cast<std::ptrdiff_t>(offset),
               data.begin() + static_cast<std::ptrdiff_t>(offset + size));
}

TEST(Mp4Bytes, DecoderSpecificInfoIsTheFourteenBytes) {
  const Bytes expected = {0x00, 0x00, 0x01, 0xB0, 0x63, 0x00, 0x00, 0x01, 0xB5, 0x23, 0x00, 0x00, 0x01, 0xBA};
  EXPECT_EQ(fba_decoder_specific_info(), expected);
  EXPECT_TRUE(declares_fba_object(expected));
}

TEST(Mp4Bytes, InitialObjectDescriptorMatchesGpac) {
  // GPAC's iods payload: 10 13 00 4F 01 FE 00 01 FE 0E 04 00000001 0E 04 00000002.
  const Bytes gpac = {0x10, 0x13, 0x00, 0x4F, 0x01, 0xFE, 0x00, 0x01, 0xFE, 0x0E, 0x04,
                      0x00, 0x00, 0x00, 0x01, 0x0E, 0x04, 0x00, 0x00, 0x00, 0x02};
  InitialObjectDescriptor iod{1, {0x01, 0xFE, 0x00, 0x01, 0xFE}, {1, 2}};
  EXPECT_EQ(encode_initial_object_descriptor(iod), gpac);
  auto back = decode_initial_object_descriptor(gpac, 0, "gpac");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(*back, iod);
}

TEST(Mp4Bytes, WrittenIodDiffersFromGpacOnlyInAudioAndVisualLevels) {
  auto bytes = write_mp4(test::hand_made_track());
  ASSERT_TRUE(bytes.ok());
  auto mp4 = read_mp4(*bytes, "t.mp4");
  ASSERT_TRUE(mp4.ok());
  // Audio 0xFF ("none required") where GPAC leaves 0x00 (reserved); visual 0x63 Simple FBA.
  const ProfileLevels expected{0x01, 0xFE, 0xFF, 0x63, 0xFE};
  EXPECT_EQ(mp4->iod->profiles, expected);
}

TEST(Mp4Bytes, ObjectDescriptorUpdateMatchesGpac) {
  // GPAC's OD sample: 01 08 11 06 02 9F 0F 02 00 01 (OD ID 10, ES_ID_Ref index 1).
  const Bytes gpac = {0x01, 0x08, 0x11, 0x06, 0x02, 0x9F, 0x0F, 0x02, 0x00, 0x01};
  EXPECT_EQ(encode_object_descriptor_update({{10, {1}}}), gpac);
  auto mp4 = read_mp4(*write_mp4(test::hand_made_track()), "t.mp4");
  ASSERT_TRUE(mp4.ok());
  const Mp4Track* od = mp4->track(kOdTrackId);
  ASSERT_NE(od, nullptr);
  ASSERT_EQ(od->samples.size(), 1U);
  EXPECT_EQ(mp4->sample_bytes(od->samples[0]), gpac);
  EXPECT_EQ(od->mpod, std::vector<std::uint32_t>{kFbaTrackId});
}

TEST(Mp4Bytes, FbaEsdsMatchesGpac) {
  // GPAC's esds payload for 10 samples of 8 bytes at 25 fps:
  // 03 25 0000 00 | 04 1D 20 11 000008 00000640 00000640 | 05 0E <DSI> | 06 01 02.
  Bytes gpac = {0x03, 0x25, 0x00, 0x00, 0x00, 0x04, 0x1D, 0x20, 0x11, 0x00, 0x00,
                0x08, 0x00, 0x00, 0x06, 0x40, 0x00, 0x00, 0x06, 0x40, 0x05, 0x0E};
  const Bytes dsi = fba_decoder_specific_info();
  gpac.insert(gpac.end(), dsi.begin(), dsi.end());
  gpac.insert(gpac.end(), {0x06, 0x01, 0x02});
  auto mp4 = read_mp4(*write_mp4(test::hand_made_track(10, 25)), "t.mp4");
  ASSERT_TRUE(mp4.ok());
  const Mp4Track* fba = mp4->track(kFbaTrackId);
  ASSERT_NE(fba, nullptr);
  EXPECT_EQ(slice(mp4->data, fba->es_offset, gpac.size()), gpac);
  // The esds box ends right there: the next box is stts.
  EXPECT_EQ(slice(mp4->data, fba->es_offset + gpac.size() + 4, 4), (Bytes{'s', 't', 't', 's'}));
}

TEST(Mp4Bytes, BifsConfigMatchesGpac) {
  // GPAC's BIFSConfig for a 320x240 command stream without pixel metrics: 10 28 0A 00 07 80.
  const Bytes gpac = {0x10, 0x28, 0x0A, 0x00, 0x07, 0x80};
  EXPECT_EQ(encode_bifs_config(BifsConfig{}), gpac);
  auto back = decode_bifs_config(gpac, 0, "gpac");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(*back, BifsConfig{});
}

TEST(Mp4Bytes, SceneAccessUnitMatchesGpacsEncoder) {
  // GPAC (master of August 2026) BIFS-encodes the same scene, read from the project's own XMT-A
  // (`MP4Box -mp4` on corpus/golden/xmta/face-fba.xmt), to exactly these 21 bytes.
  const Bytes gpac = {0xC0, 0x85, 0xA1, 0xD1, 0x19, 0x05, 0x0D, 0x14, 0x03, 0x6A, 0x82,
                      0x0A, 0x92, 0x0A, 0x6A, 0x98, 0x02, 0x29, 0x32, 0xA0, 0x70};
  auto au = encode_scene_replace(face_scene(), BifsConfig{});
  ASSERT_TRUE(au.ok());
  EXPECT_EQ(*au, gpac);
  // The file carries one zero byte more, which GPAC's decoder needs to read this scene back
  // (mp4_writer.cpp says why); `MP4Box -xmt` then dumps the scene and the FBA object descriptor.
  auto mp4 = read_mp4(*write_mp4(test::hand_made_track()), "t.mp4");
  ASSERT_TRUE(mp4.ok());
  Bytes padded = gpac;
  padded.push_back(0);
  EXPECT_EQ(mp4->sample_bytes(mp4->track(kSceneTrackId)->samples.at(0)), padded);
}

TEST(Mp4Bytes, SampleTableTimingAndSync) {
  FbaTrackInput track = test::hand_made_track(6, 30, 3);
  track.samples[4].duration = 2;
  auto mp4 = read_mp4(*write_mp4(track), "t.mp4");
  ASSERT_TRUE(mp4.ok());
  const Mp4Track* fba = mp4->track(kFbaTrackId);
  ASSERT_NE(fba, nullptr);
  EXPECT_EQ(fba->timescale, 30U);
  EXPECT_EQ(fba->duration, 7U);
  std::vector<std::uint64_t> times;
  std::vector<bool> sync;
  for (const Mp4Sample& s : fba->samples) {
    times.push_back(s.decode_time);
    sync.push_back(s.sync);
  }
  EXPECT_EQ(times, (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 6}));
  EXPECT_EQ(sync, (std::vector<bool>{true, false, false, true, false, false}));
  EXPECT_EQ(mp4->duration, 233U);  // 7 frames at 30 fps, in milliseconds
}

}  // namespace
}  // namespace fapc::xmt

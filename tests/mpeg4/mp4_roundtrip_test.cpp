// The MP4 reader gives back what the writer was given: tracks, descriptors, scene, samples.
#include <gtest/gtest.h>

#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "support/test_support.hpp"
#include "test_tracks.hpp"

namespace fapc::mpeg4 {
namespace {

Mp4File written(const FbaTrackInput& track) {
  auto bytes = write_mp4(track);
  EXPECT_TRUE(bytes.ok()) << (bytes.ok() ? "" : bytes.error().message);
  auto mp4 = read_mp4(*bytes, "t.mp4");
  EXPECT_TRUE(mp4.ok()) << (mp4.ok() ? "" : format_diagnostic(mp4.error()));
  return std::move(*mp4);
}

TEST(Mp4RoundTrip, FbaTrackComesBackAsWritten) {
  FbaTrackInput track = test::hand_made_track(12, 25, 4);
  track.samples[3].duration = 3;  // a plane that skips two frames
  const Mp4File mp4 = written(track);
  auto back = read_fba_track(mp4);
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(*back, track);
  EXPECT_TRUE(mp4.warnings.empty());
}

TEST(Mp4RoundTrip, TracksAndInitialObjectDescriptor) {
  const Mp4File mp4 = written(test::hand_made_track());
  ASSERT_EQ(mp4.tracks.size(), 3U);
  EXPECT_EQ(mp4.major_brand, "mp42");
  EXPECT_EQ(mp4.tracks[0].handler, "sdsm");
  EXPECT_EQ(mp4.tracks[1].handler, "odsm");
  EXPECT_EQ(mp4.tracks[2].handler, "vide");
  EXPECT_EQ(mp4.tracks[2].sample_entry, "mp4v");
  EXPECT_EQ(mp4.tracks[2].id, kFbaTrackId);
  ASSERT_TRUE(mp4.iod.has_value());
  EXPECT_EQ(mp4.iod->profiles.visual, kSimpleFbaL1);
  EXPECT_EQ(mp4.iod->es_id_incs, (std::vector<std::uint32_t>{kSceneTrackId, kOdTrackId}));
  EXPECT_EQ(mp4.timescale, kSystemsTimescale);
  EXPECT_EQ(mp4.duration, 400U);  // 10 frames at 25 fps
}

TEST(Mp4RoundTrip, SceneAndObjectDescriptors) {
  const Mp4File mp4 = written(test::hand_made_track());
  auto scene = read_scene(mp4);
  ASSERT_TRUE(scene.ok()) << format_diagnostic(scene.error());
  EXPECT_EQ(scene->scene, face_scene());
  EXPECT_EQ(scene->config, BifsConfig{});
  auto ods = read_object_descriptors(mp4);
  ASSERT_TRUE(ods.ok()) << format_diagnostic(ods.error());
  ASSERT_EQ(ods->size(), 1U);
  EXPECT_EQ((*ods)[0].od.od_id, kFbaObjectDescriptorId);
  EXPECT_EQ((*ods)[0].track_ids, std::vector<std::uint32_t>{kFbaTrackId});
}

TEST(Mp4RoundTrip, CommandsSceneWithWiderNodeIds) {
  BifsConfig config;
  config.node_id_bits = 3;
  const SceneNode scene = face_scene(&test::frame_with_viseme());
  auto au = encode_scene_replace(scene, config);
  ASSERT_TRUE(au.ok()) << au.error().message;
  auto back = decode_scene_replace(*au, config, 0, "s");
  ASSERT_TRUE(back.ok()) << format_diagnostic(back.error());
  EXPECT_EQ(*back, scene);
}

TEST(Mp4RoundTrip, ReadsTheFileGpacBuildsFromOurXmt) {
  // corpus/mp4/gpac-three-tracks.mp4: `MP4Box -mp4` (GPAC, August 2026) on the FBA-mode XMT-A,
  // importing the FBA track from a file written from test::hand_made_track().
  const std::string path = fapc::test::corpus_dir() + "/mp4/gpac-three-tracks.mp4";
  const std::string text = fapc::test::read_text(path);
  auto mp4 = read_mp4(Bytes(text.begin(), text.end()), path);
  ASSERT_TRUE(mp4.ok()) << format_diagnostic(mp4.error());
  auto scene = read_scene(*mp4);
  ASSERT_TRUE(scene.ok()) << format_diagnostic(scene.error());
  EXPECT_EQ(scene->scene, face_scene());
  auto ods = read_object_descriptors(*mp4);
  ASSERT_TRUE(ods.ok());
  ASSERT_EQ(ods->size(), 1U);
  EXPECT_EQ((*ods)[0].track_ids, std::vector<std::uint32_t>{kFbaTrackId});
  auto track = read_fba_track(*mp4);
  ASSERT_TRUE(track.ok());
  EXPECT_EQ(*track, test::hand_made_track());
}

}  // namespace
}  // namespace fapc::mpeg4

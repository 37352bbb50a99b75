// The MP4 reader on broken files: each error names the byte offset of the box (or descriptor)
// at fault and says what is wrong; nothing is read outside the file. The inputs are written files
// with one field changed, so each expected offset was worked out from the writer's layout and
// checked against a hex dump.
#include <gtest/gtest.h>

#include <algorithm>

#include "fapc/mpeg4/bifs.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "test_tracks.hpp"

namespace fapc::xmt {
namespace {

Bytes written() { return *write_mp4(test::hand_made_track()); }

// Offset of the last box of type `type` (its size field).
std::size_t last_box(const Bytes& file, const std::string& type) {
  const auto it = std::find_end(file.begin(), file.end(), type.begin(), type.end());
  EXPECT_NE(it, file.end()) << type;
  return static_cast<std::size_t>(it - file.begin()) - 4;
}

void put_u32(Bytes& file, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) file[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (24 - 8 * i));
}

std::string error_of(const Bytes& file) {
  auto mp4 = read_mp4(file, "f.mp4");
  return mp4.ok() ? "no error" : format_diagnostic(mp4.error());
}

TEST(Mp4ReaderErrors, EmptyFileHasNoMovie) {
  EXPECT_EQ(error_of({}), "f.mp4: byte 0: error: no 'moov' box: not an MP4 file, or one without a movie");
}

TEST(Mp4ReaderErrors, StrayBytesAtTheEnd) {
  Bytes file = written();
  file.insert(file.end(), {1, 2, 3});
  EXPECT_EQ(error_of(file), "f.mp4: byte " + std::to_string(file.size() - 3) +
                                ": error: 3 stray byte(s) where a box header (8 bytes) should be");
}

TEST(Mp4ReaderErrors, BoxSmallerThanItsHeader) {
  Bytes file = written();
  put_u32(file, 0, 4);  // ftyp
  EXPECT_EQ(error_of(file), "f.mp4: byte 0: error: box 'ftyp' claims 4 bytes, less than its own header");
}

TEST(Mp4ReaderErrors, ChildOverrunsItsParent) {
  Bytes file = written();
  const std::size_t stsz = last_box(file, "stsz");
  put_u32(file, stsz, 10000);
  EXPECT_EQ(error_of(file), "f.mp4: byte " + std::to_string(stsz) + ": error: box 'stsz' claims 10000 bytes but only " +
                                std::to_string(last_box(file, "stco") - stsz + 20) + " are left in its parent");
}

TEST(Mp4ReaderErrors, TableCountsThatDoNotAddUp) {
  Bytes file = written();
  const std::size_t stts = last_box(file, "stts");
  put_u32(file, stts + 16, 9);  // 9 of the 10 samples
  EXPECT_EQ(error_of(file),
            "f.mp4: byte " + std::to_string(stts) + ": error: track 10: 'stts' describes 9 samples, 'stsz' 10");
}

TEST(Mp4ReaderErrors, SyncSampleOutOfRange) {
  Bytes file = written();
  const std::size_t stss = last_box(file, "stss");
  put_u32(file, stss + 16, 11);
  EXPECT_EQ(error_of(file), "f.mp4: byte " + std::to_string(stss) + ": error: track 10: 'stss' names sample 11 of 10");
}

TEST(Mp4ReaderErrors, EntryCountLargerThanTheBox) {
  Bytes file = written();
  const std::size_t stco = last_box(file, "stco");
  put_u32(file, stco + 12, 0x40000000);
  EXPECT_EQ(error_of(file), "f.mp4: byte " + std::to_string(stco) +
                                ": error: 'stco' box holds fewer entries than its count (1073741824)");
}

TEST(Mp4ReaderErrors, DescriptorOverrunsItsBox) {
  Bytes file = written();
  const std::size_t esds = last_box(file, "esds");
  file[esds + 13] = 0x7F;  // ES_Descriptor size
  EXPECT_EQ(error_of(file), "f.mp4: byte " + std::to_string(esds + 12) +
                                ": error: descriptor (tag 0x03) of 127 bytes overruns its container (37 bytes left)");
}

TEST(Mp4ReaderErrors, OdReferenceBeyondMpod) {
  Bytes file = written();
  // The OD sample is the second sample in mdat: 01 08 11 06 02 9F 0F 02 00 01.
  const Bytes od = {0x01, 0x08, 0x11, 0x06, 0x02, 0x9F, 0x0F, 0x02, 0x00, 0x01};
  const auto at = static_cast<std::size_t>(std::search(file.begin(), file.end(), od.begin(), od.end()) - file.begin());
  file[at + 9] = 2;
  auto mp4 = read_mp4(file, "f.mp4");
  ASSERT_TRUE(mp4.ok());
  auto ods = read_object_descriptors(*mp4);
  ASSERT_FALSE(ods.ok());
  EXPECT_EQ(format_diagnostic(ods.error()),
            "f.mp4: byte " + std::to_string(at) +
                ": error: object descriptor 10 refers to stream 2 of the OD track's 1 'mpod' references");
}

TEST(Mp4ReaderErrors, NoFbaTrackInAFileWithoutOne) {
  Bytes file = written();
  // Turn the FBA configuration's visual object type (FBA, 4) into video object (1).
  const std::size_t esds = last_box(file, "esds");
  const std::size_t type_byte = esds + 12 + 2 + 3 + 2 + 13 + 2 + 9;
  ASSERT_EQ(file[type_byte], 0x23);
  file[type_byte] = 0x09;
  auto mp4 = read_mp4(file, "f.mp4");
  ASSERT_TRUE(mp4.ok());
  EXPECT_EQ(find_fba_track(*mp4), nullptr);
  EXPECT_FALSE(read_fba_track(*mp4).ok());
}

TEST(BifsErrors, NodesOutsideTheSubsetAreNamed) {
  SceneNode scene = face_scene();
  scene.fields[0].value = std::vector<SceneNode>{SceneNode{"Transform", {}, {}}};
  auto au = encode_scene_replace(scene, BifsConfig{});
  ASSERT_FALSE(au.ok());
  EXPECT_EQ(
      au.error().message,
      "BIFS encoding: cannot code node Transform as SF3DNode (in Group.children): not in the BIFS subset fapc writes");
}

TEST(BifsErrors, TooManyDefNamesForTheNodeIdBits) {
  // FACE, PARAMS, VISEME, EXPRESSION: IDs 1..4; with 2 bits, ID 4 (coded 11) is the reserved
  // all-ones value.
  auto au = encode_scene_replace(face_scene(&test::frame_with_viseme()), BifsConfig{});
  ASSERT_FALSE(au.ok());
  EXPECT_EQ(au.error().message, "BIFS encoding: node EXPRESSION gets ID 4, which 2-bit node IDs cannot hold");
  BifsConfig wider;
  wider.node_id_bits = 3;
  EXPECT_TRUE(encode_scene_replace(face_scene(&test::frame_with_viseme()), wider).ok());
}

TEST(BifsErrors, DecoderStopsAtTheFirstUnknownThing) {
  const Bytes good = *encode_scene_replace(face_scene(), BifsConfig{});
  // Cut short: the error names the byte where the data ran out.
  Bytes cut(good.begin(), good.begin() + 12);
  auto decoded = decode_scene_replace(cut, BifsConfig{}, 100, "s");
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(format_diagnostic(decoded.error()), "s: byte 112: error: BIFS: scene access unit ends inside a node");
  // A Face coded as node type 15 of SF3DNode (Fog): outside the subset. Face's 6-bit code is
  // bits 21..26 of the unit; its last bit is bit 2 of byte 3.
  Bytes fog = good;
  fog[3] = static_cast<std::uint8_t>(fog[3] ^ 0x20);  // 001110 -> 001111
  decoded = decode_scene_replace(fog, BifsConfig{}, 0, "s");
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(format_diagnostic(decoded.error()),
            "s: byte 3: error: BIFS: SF3DNode node type 15 is outside the node subset fapc decodes");
  // Non-zero data after the command.
  Bytes trailing = good;
  trailing.push_back(0x01);
  decoded = decode_scene_replace(trailing, BifsConfig{}, 0, "s");
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(decoded.error().message, "BIFS: data after the SceneReplace command");
}

}  // namespace
}  // namespace fapc::xmt

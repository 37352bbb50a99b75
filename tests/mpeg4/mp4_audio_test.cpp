// The voice in the MP4: the audio track, its object descriptor and the scene's Sound2D, checked
// against bits and bytes worked out by hand from the syntax of ISO/IEC 14496-1 (descriptors),
// 14496-11 (BIFS; node codes from the version 1 node tables, as GPAC's tables give them) and
// 14496-12/14 (boxes). The access units here are placeholders: nothing in fapc::mpeg4 decodes
// audio (tests/audio_codec does, with real AAC).
#include <gtest/gtest.h>

#include <string>

#include "fapc/mpeg4/bifs.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "fapc/mpeg4/object_descriptors.hpp"
#include "fapc/mpeg4/scene.hpp"
#include "test_tracks.hpp"

namespace fapc::xmt {
namespace {

std::string bit_string(const Bytes& bytes) {
  std::string out;
  for (std::uint8_t b : bytes)
    for (int i = 7; i >= 0; --i) out += ((b >> i) & 1) ? '1' : '0';
  return out;
}

Bytes from_bits(std::string bits) {
  while (bits.size() % 8) bits += '0';
  Bytes out;
  for (std::size_t i = 0; i < bits.size(); i += 8)
    out.push_back(static_cast<std::uint8_t>(std::stoi(bits.substr(i, 8), nullptr, 2)));
  return out;
}

// Mono AAC-LC at 22050 Hz: 00010 0111 0001 000 (object type 2, frequency index 7, one channel).
const Bytes kAsc22050 = {0x13, 0x88};

AudioTrackInput hand_made_audio(int units = 12, std::uint32_t delay_ms = 0) {
  AudioTrackInput a;
  a.decoder_specific_info = kAsc22050;
  a.sample_rate = 22050;
  for (int i = 0; i < units; ++i) a.samples.push_back(Bytes{0x21, static_cast<std::uint8_t>(i), 0x00, 0x07});
  a.media_start = 1024;  // the encoder's priming
  a.length = 22050 / 2;  // half a second of sound
  a.delay_ms = delay_ms;
  return a;
}

TEST(Mp4Audio, SceneGainsSound2DWithAudioSourceNamingTheAudioOd) {
  // The scene without sound ends with the Group's end-of-children bit, then "no ROUTEs" and "no
  // more commands" (two 0 bits), then padding: its last 1 bit is that end bit.
  auto plain = encode_scene_replace(face_scene(), BifsConfig{});
  ASSERT_TRUE(plain.ok());
  const std::string bits = bit_string(*plain);
  const std::size_t group_end = bits.rfind('1');
  // By hand: MFURL = reserved 0, list 1, [not end 0, isOD 1, OD ID 11 in 10 bits], end 1.
  const std::string url =
      "0"
      "1"
      "0"
      "1"
      "0000001011"
      "1";
  // AudioSource as SFAudioNode (3-bit codes, AudioSource = 6): not USE, 110, not DEF; 8 fields so
  // 3-bit indexes; list mode (a mask would cost 8 bits, the list 1 + 4 + 1); field 1 (url); end.
  const std::string source =
      "0"
      "110"
      "0"
      "0"
      "0"
      "001" +
      url + "1";
  // Sound2D as SF3DNode (6-bit codes, Sound2D = 40): not USE, 101000, not DEF; 4 fields so 2-bit
  // indexes; list mode (4 mask bits are not fewer than 1 + 3); field 2 (source); end.
  const std::string sound =
      "0"
      "101000"
      "0"
      "0"
      "0"
      "10" +
      source + "1";
  const std::string expected = bits.substr(0, group_end) + "0" + sound + "1" + "00";
  auto with = encode_scene_replace(with_sound(face_scene(), kAudioObjectDescriptorId), BifsConfig{});
  ASSERT_TRUE(with.ok()) << with.error().message;
  EXPECT_EQ(*with, from_bits(expected));
  auto back = decode_scene_replace(*with, BifsConfig{}, 0, "t");
  ASSERT_TRUE(back.ok()) << format_diagnostic(back.error());
  EXPECT_EQ(*back, with_sound(face_scene(), kAudioObjectDescriptorId));
  EXPECT_EQ(scene_text(*back).find("Sound2D { source AudioSource { url [ \"od:11\" ] } }") != std::string::npos, true)
      << scene_text(*back);
}

TEST(Mp4Audio, ObjectDescriptorUpdateDeclaresBothStreams) {
  // ObjectDescriptorUpdate (01), 16 bytes: MP4_OD (11) of 6 bytes each. 02 9F = OD ID 10, no URL,
  // reserved 11111; 02 DF = OD ID 11 likewise; ES_ID_Ref (0F) 2 bytes: index 1, then index 2.
  const Bytes expected = {0x01, 0x10, 0x11, 0x06, 0x02, 0x9F, 0x0F, 0x02, 0x00,
                          0x01, 0x11, 0x06, 0x02, 0xDF, 0x0F, 0x02, 0x00, 0x02};
  const AudioTrackInput audio = hand_made_audio();
  auto mp4 = read_mp4(*write_mp4(test::hand_made_track(), &audio), "t.mp4");
  ASSERT_TRUE(mp4.ok()) << format_diagnostic(mp4.error());
  const Mp4Track* od = mp4->track(kOdTrackId);
  ASSERT_NE(od, nullptr);
  EXPECT_EQ(mp4->sample_bytes(od->samples.at(0)), expected);
  EXPECT_EQ(od->mpod, (std::vector<std::uint32_t>{kFbaTrackId, kAudioTrackId}));
  auto objects = read_object_descriptors(*mp4);
  ASSERT_TRUE(objects.ok());
  ASSERT_EQ(objects->size(), 2U);
  EXPECT_EQ((*objects)[1].od.od_id, kAudioObjectDescriptorId);
  EXPECT_EQ((*objects)[1].track_ids, std::vector<std::uint32_t>{kAudioTrackId});
}

TEST(Mp4Audio, AudioTrackBoxesAndDescriptor) {
  const AudioTrackInput audio = hand_made_audio(12, 40);
  auto mp4 = read_mp4(*write_mp4(test::hand_made_track(), &audio), "t.mp4");
  ASSERT_TRUE(mp4.ok()) << format_diagnostic(mp4.error());
  EXPECT_TRUE(mp4->warnings.empty());  // the audio track's edit list is read, not ignored
  ASSERT_EQ(mp4->tracks.size(), 4U);
  const Mp4Track* t = find_audio_track(*mp4);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->id, kAudioTrackId);
  EXPECT_EQ(t->handler, "soun");
  EXPECT_EQ(t->sample_entry, "mp4a");
  EXPECT_EQ(t->timescale, 22050U);
  EXPECT_EQ(t->duration, 12U * 1024U);
  // 12 units of 4 bytes over 12288/22050 s: 689 bit/s on average; the maximum is never below it
  // (all 384 bits fall within one second).
  // ES_Descriptor (03) 25 bytes, ES_ID 0, no flags; DecoderConfigDescriptor (04) 17 bytes:
  // OTI 0x40, stream type 5 << 2 | reserved 1 = 0x15, bufferSizeDB 4, max 689, avg 689;
  // DecoderSpecificInfo (05) the 2-byte AudioSpecificConfig; SLConfigDescriptor (06) predefined 2.
  const Bytes esds = {0x03, 0x19, 0x00, 0x00, 0x00, 0x04, 0x11, 0x40, 0x15, 0x00, 0x00, 0x04, 0x00, 0x00,
                      0x02, 0xB1, 0x00, 0x00, 0x02, 0xB1, 0x05, 0x02, 0x13, 0x88, 0x06, 0x01, 0x02};
  EXPECT_EQ(Bytes(mp4->data.begin() + static_cast<std::ptrdiff_t>(t->es_offset),
                  mp4->data.begin() + static_cast<std::ptrdiff_t>(t->es_offset + esds.size())),
            esds);
  // An empty edit of 40 ms, then the sound: 500 ms from media time 1024 (the priming).
  EXPECT_EQ(t->edits, (std::vector<Mp4Edit>{{40, -1}, {500, 1024}}));
  // AAC Profile @ Level 1 (0x28): AAC-LC up to 24 kHz.
  EXPECT_EQ(mp4->iod->profiles.audio, 0x28);
  // The movie lasts as long as its longest track: 40 + 500 ms of voice against 400 ms of face.
  EXPECT_EQ(mp4->duration, 540U);
  auto back = read_audio_track(*mp4, *t);
  ASSERT_TRUE(back.ok()) << format_diagnostic(back.error());
  EXPECT_EQ(*back, audio);
}

TEST(Mp4Audio, WithoutAudioTheFileIsTheThreeTrackOne) {
  auto plain = write_mp4(test::hand_made_track());
  auto none = write_mp4(test::hand_made_track(), nullptr);
  ASSERT_TRUE(plain.ok() && none.ok());
  EXPECT_EQ(*plain, *none);
  auto mp4 = read_mp4(*plain, "t.mp4");
  ASSERT_TRUE(mp4.ok());
  EXPECT_EQ(find_audio_track(*mp4), nullptr);
}

TEST(Mp4Audio, RejectsAudioTheAccessUnitsCannotHold) {
  AudioTrackInput audio = hand_made_audio(2);
  audio.length = 2 * 1024;  // plus the 1024 priming samples: more than two units hold
  auto bytes = write_mp4(test::hand_made_track(), &audio);
  ASSERT_FALSE(bytes.ok());
  EXPECT_NE(bytes.error().message.find("3072 samples of sound in access units holding 2048"), std::string::npos)
      << bytes.error().message;
}

}  // namespace
}  // namespace fapc::xmt

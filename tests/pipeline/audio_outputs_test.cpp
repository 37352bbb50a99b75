// The voice in the outputs, end to end through the pipeline: a Loaded with audio written as .mp4
// (AAC track), .webm/.html (Opus) and .xmt (AudioSource/Sound2D, the audio OD), then read by the
// outside readers (ffprobe, MediaInfo, ffmpeg decoding) and by fapc itself (load, info, verify).
// The audio is a tone with silences built here: a sound whose every stretch is known.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "fapc/pipeline/info.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/pipeline/validate.hpp"
#include "fapc/pipeline/verify.hpp"
#include "pipeline_test_helpers.hpp"
#include "support/test_support.hpp"
#include "tone.hpp"

namespace fapc::pipeline {
namespace {

constexpr int kRate = 22050;

// joy.fap: 108 frames at 25 fps, 4.32 s.
Loaded face_with_voice(double start = 0) {
  auto loaded = load(test::corpus_dir() + "/examples/fap/joy.fap", ConvertOptions{});
  EXPECT_TRUE(loaded.ok());
  loaded->audio = test::tone_with_silences(kRate, start);
  return std::move(*loaded);
}

std::string write(const Loaded& loaded, const std::string& path) {
  const OutputFormat* format = formats().output_for(path);
  EXPECT_NE(format, nullptr);
  auto bytes = format->write(loaded, path, ConvertOptions{});
  EXPECT_TRUE(bytes.ok()) << (bytes.ok() ? "" : format_diagnostic(bytes.error()));
  std::ofstream(path, std::ios::binary) << (bytes.ok() ? *bytes : "");
  return path;
}

// The value of `key=` in ffprobe's block for the stream of `type` (audio, video, data).
std::string probe_field(const std::string& out, const std::string& type, const std::string& key) {
  std::size_t at = out.find("codec_type=" + type + "\n");
  if (at == std::string::npos) return "(no " + type + " stream)";
  const std::size_t block = out.rfind("[STREAM]", at);
  const std::size_t end = out.find("[/STREAM]", at);
  const std::size_t k = out.find("\n" + key + "=", block);
  if (k == std::string::npos || k > end) return "(no " + key + ")";
  const std::size_t from = k + key.size() + 2;
  return out.substr(from, out.find('\n', from) - from);
}

// ffmpeg decodes the audio stream from start to end without a word on stderr. Its MPEG-4 Part 2
// *video* decoder, which tries the FBA planes while probing the file (it has no FBA decoder),
// may complain; those lines are about the FBA track (tests/mpeg4/outside_readers_test.cpp).
void expect_audio_decodes(const std::string& path) {
  const auto run = test::run_shell("ffmpeg -nostdin -v error -i '" + path + "' -map 0:a -f null - 2>&1");
  EXPECT_EQ(run.exit_status, 0) << run.out;
  std::istringstream lines(run.out);
  std::string line, rest;
  bool after_video_decoder = false;
  while (std::getline(lines, line)) {
    const bool video_decoder = line.rfind("[mpeg4 @", 0) == 0;
    const bool repeat = line.find("Last message repeated") != std::string::npos;
    if (!video_decoder && !(repeat && after_video_decoder)) rest += line + '\n';
    after_video_decoder = video_decoder || (repeat && after_video_decoder);
  }
  EXPECT_EQ(rest, "");
}

TEST(AudioOutputs, Mp4HasAnAacTrackTheOutsideReadersSeeAndDecode) {
  test::TempFolder dir;
  const std::string path = write(face_with_voice(), dir / "voice.mp4");
  const auto probe = test::run_shell("ffprobe -v error -show_streams '" + path + "' 2>/dev/null");
  ASSERT_EQ(probe.exit_status, 0);
  EXPECT_EQ(probe_field(probe.out, "audio", "codec_name"), "aac");
  EXPECT_EQ(probe_field(probe.out, "audio", "profile"), "LC");
  EXPECT_EQ(probe_field(probe.out, "audio", "sample_rate"), "22050");
  EXPECT_EQ(probe_field(probe.out, "audio", "channels"), "1");
  // The voice is padded with silence to the face's 4.32 s; ffprobe reads the edit list.
  EXPECT_EQ(probe_field(probe.out, "audio", "duration"), "4.320000");
  EXPECT_EQ(probe_field(probe.out, "audio", "start_time"), "0.000000");
  EXPECT_EQ(probe_field(probe.out, "video", "codec_name"), "mpeg4");  // the FBA track is still there
  const auto info = test::run_shell("mediainfo '" + path + "'");
  EXPECT_NE(info.out.find("Format                                   : AAC LC"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("Sampling rate                            : 22.05 kHz"), std::string::npos);
  EXPECT_NE(info.out.find("Duration                                 : 4 s 320 ms"), std::string::npos);
  expect_audio_decodes(path);
}

TEST(AudioOutputs, Mp4RoundTripGivesTheVoiceBack) {
  test::TempFolder dir;
  const std::string path = write(face_with_voice(0.3), dir / "late.mp4");
  auto back = load(path, ConvertOptions{});
  ASSERT_TRUE(back.ok()) << format_diagnostic(back.error());
  ASSERT_TRUE(back->audio.has_value());
  EXPECT_EQ(back->audio->sample_rate, kRate);
  EXPECT_DOUBLE_EQ(back->audio->start, 0.3);
  // 4.32 s of face from 0.3 s: 4.02 s of sound (1.6 s of tone stretches, then silence).
  EXPECT_NEAR(back->audio->duration(), 4.02, 0.001);
  for (const auto& [from, to, loud] : test::tone_segments(kRate)) {
    const double rms = test::rms(back->audio->samples, from + 220, to - 220);
    if (loud)
      EXPECT_GT(rms, 5000.0) << from;
    else
      EXPECT_LT(rms, 100.0) << from;
  }
  const auto probe = test::run_shell("ffprobe -v error -show_streams '" + path + "' 2>/dev/null");
  EXPECT_EQ(probe_field(probe.out, "audio", "start_time"), "0.300000");
}

TEST(AudioOutputs, InfoReportsTheAudioAndVerifyChecksItsSpan) {
  test::TempFolder dir;
  const std::string path = write(face_with_voice(0.3), dir / "voice.mp4");
  auto info = describe(path);
  ASSERT_TRUE(info.ok());
  const auto& format = (*info)["format"];
  EXPECT_EQ(format["audio_codec"], "AAC-LC (mp4a.40.2)");
  EXPECT_EQ(format["audio_sample_rate"], kRate);
  EXPECT_EQ(format["audio_channels"], 1);
  EXPECT_NEAR(format["audio_duration"].get<double>(), 4.02, 0.001);
  EXPECT_DOUBLE_EQ(format["audio_start"].get<double>(), 0.3);
  const VerifyResult ok = verify(path, ConvertOptions{});
  EXPECT_TRUE(ok.ok()) << (ok.error ? format_diagnostic(*ok.error) : "");

  // A voice two seconds longer than the face.
  Loaded longer = face_with_voice();
  longer.audio->samples.resize(static_cast<std::size_t>(6.32 * kRate), 0);
  const std::string bad = write(longer, dir / "longer.mp4");
  const VerifyResult failed = verify(bad, ConvertOptions{});
  ASSERT_FALSE(failed.ok());
  EXPECT_EQ(failed.error->kind, ErrorKind::verification_failed);
  EXPECT_NE(failed.error->message.find("the audio track ends at 6.320 s, the face track at 4.320 s"), std::string::npos)
      << failed.error->message;
}

TEST(AudioOutputs, WebmCarriesOpusAndThePageIsNotMuted) {
  test::TempFolder dir;
  const Loaded loaded = face_with_voice(0.5);
  const std::string path = write(loaded, dir / "voice.webm");
  const auto probe = test::run_shell("ffprobe -v error -show_streams '" + path + "' 2>/dev/null");
  ASSERT_EQ(probe.exit_status, 0);
  EXPECT_EQ(probe_field(probe.out, "audio", "codec_name"), "opus");
  EXPECT_EQ(probe_field(probe.out, "audio", "sample_rate"), "48000");
  EXPECT_EQ(probe_field(probe.out, "video", "codec_name"), "vp9");
  expect_audio_decodes(path);
  // The voice starts at 0.5 s: ffmpeg's decoded audio begins there (give or take Opus's 20 ms
  // frames and its pre-skip).
  const auto first = test::run_shell("ffprobe -v error -select_streams a -show_entries packet=pts_time -of csv=p=0 '" +
                                     path + "' 2>/dev/null | head -1");
  EXPECT_NEAR(std::stod(first.out), 0.5, 0.03) << first.out;
  const std::string page = test::read_text(write(loaded, dir / "voice.html"));
  EXPECT_EQ(page.find(" muted "), std::string::npos);
  Loaded silent = loaded;
  silent.audio.reset();
  EXPECT_NE(test::read_text(write(silent, dir / "silent.html")).find(" muted "), std::string::npos);
}

TEST(AudioOutputs, XmtaDeclaresTheAudioStreamAndPlaysItInTheScene) {
  test::TempFolder dir;
  const std::string path = write(face_with_voice(), dir / "voice.xmt");
  const std::string xmt = test::read_text(path);
  EXPECT_NE(xmt.find("<DecoderConfigDescriptor streamType=\"5\" objectTypeIndication=\"64\">"), std::string::npos)
      << xmt;
  EXPECT_NE(xmt.find("src=\"data:application/octet-string,%13%88%56%E5%00\""), std::string::npos);
  EXPECT_NE(xmt.find("<StreamSource url=\"voice.mp4#11\"/>"), std::string::npos);
  EXPECT_NE(xmt.find("<AudioSource url=\"&quot;od:11&quot;\"/>"), std::string::npos);
  EXPECT_NE(xmt.find("audioProfileLevelIndication=\"40\""), std::string::npos);
  auto report = validate(path);
  ASSERT_TRUE(report.ok());
  EXPECT_TRUE(report->valid());
}

}  // namespace
}  // namespace fapc::pipeline

// Sync you can measure (docs/speech.md, "Measured sync"): FML talk text spoken by the real engine,
// rendered to frames; speech onsets and pauses found in the audio itself by its energy; the mouth
// (any viseme weight in the rendered FAP 1) must open and close with them within one frame. And a
// bilabial (p, b, m) shows the closed-lips viseme PP at that phoneme's time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <filesystem>
#include <fstream>

#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/engine.hpp"
#include "support/test_support.hpp"
#include "support/voiced_segments.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

constexpr int kFps = 25;
constexpr double kFrame = 1.0 / kFps;

std::string write_fml(const std::string& name, const std::string& talks) {
  const fs::path dir = test::scratch_folder("speech-test");
  const fs::path path = dir / name;
  std::ofstream(path) << "<fml><story><action>" << talks << "</action></story></fml>\n";
  return path.string();
}

pipeline::Loaded load_spoken(const std::string& path) {
  pipeline::ConvertOptions options;
  options.fps = kFps;
  Result<pipeline::Loaded> loaded = pipeline::load(path, options);
  EXPECT_TRUE(loaded) << (loaded ? "" : loaded.error().message);
  if (!loaded) return {};
  EXPECT_TRUE(loaded->audio.has_value());
  return std::move(*loaded);
}

using test::Segment;
using test::voiced_segments;

// Where the mouth is away from neutral: frames whose FAP 1 carries a viseme with weight, joined
// the same way (a frame is an instant: a segment runs from its first to its last such frame).
std::vector<Segment> mouth_segments(const FapSequence& frames, double min_pause) {
  std::vector<Segment> out;
  for (const FapFrame& f : frames.frames) {
    const bool moving = f.has(1) && f.viseme.select1 > 0 && (f.viseme.blend > 0 || f.viseme.select2 > 0);
    if (!moving) continue;
    const double t = double(f.number) / frames.fps;
    if (!out.empty() && t - out.back().end < min_pause) {
      out.back().end = t;
    } else {
      out.push_back({t, t});
    }
  }
  return out;
}

void expect_in_sync_file(const std::string& path) {
  SCOPED_TRACE(path);
  const pipeline::Loaded loaded = load_spoken(path);
  ASSERT_TRUE(loaded.audio);
  const double min_pause = 0.1;
  const std::vector<Segment> voice = voiced_segments(*loaded.audio, min_pause);
  // Any neutral frame splits the mouth's stretches: inside speech the mouth never rests.
  const std::vector<Segment> mouth = mouth_segments(loaded.frames, 1.5 * kFrame);
  ASSERT_GE(voice.size(), 2u) << "the sentences should be heard as separate stretches";
  std::string both;
  for (const Segment& v : voice) both += " voice " + std::to_string(v.begin) + "-" + std::to_string(v.end);
  for (const Segment& m : mouth) both += " mouth " + std::to_string(m.begin) + "-" + std::to_string(m.end);
  ASSERT_EQ(voice.size(), mouth.size()) << both;
  double worst_onset = 0;
  double worst_end = 0;
  for (std::size_t i = 0; i < voice.size(); ++i) {
    worst_onset = std::max(worst_onset, std::abs(mouth[i].begin - voice[i].begin));
    worst_end = std::max(worst_end, std::abs(mouth[i].end - voice[i].end));
  }
  // The figures docs/speech.md reports ("Measured sync").
  std::printf("%s: %zu stretches, worst onset %.0f ms, worst end %.0f ms\n", path.c_str(), voice.size(),
              worst_onset * 1000, worst_end * 1000);
  for (std::size_t i = 0; i < voice.size(); ++i) {
    SCOPED_TRACE("stretch " + std::to_string(i));
    // Within one frame: the frame grid cannot place an edge closer than that.
    EXPECT_NEAR(mouth[i].begin, voice[i].begin, kFrame + 0.01);
    EXPECT_NEAR(mouth[i].end, voice[i].end, kFrame + 0.01);
  }
}

void expect_in_sync(const std::string& name, const std::string& talks) { expect_in_sync_file(write_fml(name, talks)); }

TEST(SpeechSync, MouthOpensAndClosesWithTheVoiceEnglish) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  expect_in_sync("english.fml",
                 "<talk>Hello, my name is Alice. I live in a small town.</talk>"
                 "<wait duration=\"0.5\"/><talk>Good morning to you.</talk>");
}

TEST(SpeechSync, MouthOpensAndClosesWithTheVoiceFrench) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  expect_in_sync("french.fml", "<talk lang=\"fr\">Bonjour, je m'appelle Alice. Il fait beau.</talk>");
}

TEST(SpeechSync, TwoLanguagesExample) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  expect_in_sync_file(test::corpus_dir() + "/examples/fml/two-languages.fml");
}

TEST(SpeechSync, BilabialsCloseTheLips) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  const std::string text = "Peter bought a map. Bob made more.";
  const pipeline::Loaded loaded = load_spoken(write_fml("bilabial.fml", "<talk>" + text + "</talk>"));
  // The same request, straight to the engine, for the phoneme times (the engine is deterministic).
  SpeechRequest request;
  request.text = text;
  Result<Utterance> spoken = speech::engine()(request);
  ASSERT_TRUE(spoken) << spoken.error().message;
  int bilabials = 0;
  for (const SpokenPhoneme& p : spoken->phonemes) {
    if (p.name != "p" && p.name != "b" && p.name != "m") continue;
    ++bilabials;
    const double centre = (p.begin + p.end) / 2;
    const auto frame = static_cast<std::size_t>(std::lround(centre * kFps));
    ASSERT_LT(frame, loaded.frames.frames.size());
    const FapFrame& f = loaded.frames.frames[frame];
    EXPECT_EQ(f.viseme.select1, 1) << p.name << " at " << centre << " s (frame " << frame << ")";
  }
  EXPECT_GE(bilabials, 6);  // p, b, m, b, b, m, m: the text has seven
}

}  // namespace
}  // namespace fapc

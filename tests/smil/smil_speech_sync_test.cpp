// An affect or action anchored to a speech mark starts with the marked word, measured on the
// audio as the BML and FML speech sync tests measure it: the word after a sentence pause is heard
// as a new voiced stretch (support/voiced_segments.hpp), whose onset must be within one frame of
// the first rendered frame where the anchored behaviour moves the face.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/engine.hpp"
#include "support/voiced_segments.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

constexpr int kFps = 25;
constexpr double kFrame = 1.0 / kFps;

std::string write_smil(const std::string& body) {
  const fs::path dir = fs::temp_directory_path() / ("fapc-smil-sync-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / "sync.smil";
  std::ofstream(path) << body;
  return path.string();
}

// The time of the frame before the first where FAP `fap` is away from 0.
double first_move(const FapSequence& frames, int fap) {
  for (const FapFrame& f : frames.frames)
    if (f.has(fap) && f.value(fap) != 0) return double(f.number - 1) / frames.fps;
  return -1;
}

void expect_synced(const std::string& body, int fap, std::size_t stretch) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  pipeline::ConvertOptions options;
  options.fps = kFps;
  Result<pipeline::Loaded> loaded = pipeline::load(write_smil(body), options);
  ASSERT_TRUE(loaded) << format_diagnostic(loaded.error());
  ASSERT_TRUE(loaded->audio);
  std::vector<double> onsets;
  for (const test::Segment& segment : test::voiced_segments(*loaded->audio, 0.1)) onsets.push_back(segment.begin);
  ASSERT_GT(onsets.size(), stretch) << "the marked word should follow a pause";
  const double moved = first_move(loaded->frames, fap);
  std::printf("word onset %.3f s, behaviour starts %.3f s\n", onsets[stretch], moved);
  EXPECT_NEAR(moved, onsets[stretch], kFrame + 0.01);
}

TEST(SmilSpeechSync, AnAffectAnchoredToAMarkStartsWithTheMarkedWord) {
  // FAP 31, raise_l_i_eyebrow: Surprise raises the brows.
  expect_synced(R"(<par system-language="english">
  <speech channel="alice-voice" id="s1">Good morning to you. <mark id="*1*"/>Look at this.</speech>
  <speech-animation affect="Surprise" content-id="s1" content-begin="*1*"/>
</par>)",
                31, 1);
}

TEST(SmilSpeechSync, AnActionAnchoredToAMarkInALaterSpeechStartsWithItsWord) {
  // FAP 23, yaw_l_eyeball: LookLeft turns the eyes; the speech starts after another in a seq.
  expect_synced(R"(<par system-language="english">
  <seq>
    <speech channel="alice-voice" id="s0">Hello.</speech>
    <speech channel="alice-voice" id="s1" begin="0.5s">I am here. <mark id="m"/>Really here.</speech>
  </seq>
  <action channel="alice-eyes" action-type="turning" content-id="s1" content-begin="m"><parameter>LookLeft</parameter></action>
</par>)",
                23, 2);
}

}  // namespace
}  // namespace fapc

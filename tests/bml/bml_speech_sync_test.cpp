// A behaviour synced to a speech mark starts with the marked word, measured on the audio as
// tests/speech/speech_sync_test.cpp measures the mouth: the word after a sentence pause is heard
// as a new voiced stretch, whose onset (found by energy) must be within one frame of the first
// rendered frame where the synced behaviour moves the face.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
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

// Onsets of the voiced stretches (support/voiced_segments.hpp), joined across gaps shorter than
// min_pause.
std::vector<double> voiced_onsets(const AudioTrack& track, double min_pause) {
  std::vector<double> onsets;
  for (const test::Segment& segment : test::voiced_segments(track, min_pause)) onsets.push_back(segment.begin);
  return onsets;
}

std::string write_bml(const std::string& name, const std::string& body) {
  const fs::path dir = fs::temp_directory_path() / ("fapc-bml-sync-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << "<bml xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\" id=\"b1\">" << body << "</bml>\n";
  return path.string();
}

// The time of the frame before the first where FAP `fap` is away from 0: the behaviour's start
// lies between that frame and the next.
double first_move(const FapSequence& frames, int fap) {
  for (const FapFrame& f : frames.frames)
    if (f.has(fap) && f.value(fap) != 0) return double(f.number - 1) / frames.fps;
  return -1;
}

void expect_synced(const std::string& body, int fap, std::size_t stretch) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  pipeline::ConvertOptions options;
  options.fps = kFps;
  Result<pipeline::Loaded> loaded = pipeline::load(write_bml("sync.bml", body), options);
  ASSERT_TRUE(loaded) << loaded.error().message;
  ASSERT_TRUE(loaded->audio);
  const std::vector<double> onsets = voiced_onsets(*loaded->audio, 0.1);
  ASSERT_GT(onsets.size(), stretch) << "the marked word should follow a pause";
  const double moved = first_move(loaded->frames, fap);
  std::printf("word onset %.3f s, behaviour starts %.3f s\n", onsets[stretch], moved);
  EXPECT_NEAR(moved, onsets[stretch], kFrame + 0.01);
}

TEST(BmlSpeechSync, ANodSyncedToAMarkStartsWithTheMarkedWord) {
  expect_synced(R"(<speech id="s1"><text>Good morning to you. <sync id="m1"/>Look at this.</text></speech>
                   <head id="n1" lexeme="NOD" start="s1:m1"/>)",
                48, 1);
}

TEST(BmlSpeechSync, ABrowRaiseSyncedByAConstraintStartsWithItsWord) {
  expect_synced(R"(<speech id="s1" start="0.5"><text>Hello. I am here. <sync id="m2"/>Really here.</text></speech>
                   <faceLexeme id="f1" lexeme="RAISE_BROWS"/>
                   <constraint><synchronize><sync ref="s1:m2"/><sync ref="f1:start"/></synchronize></constraint>)",
                31, 2);
}

}  // namespace
}  // namespace fapc

// An intention anchored to a speech mark (FML-APML) or put on a word (APML) starts with that word,
// measured on the audio as tests/bml/bml_speech_sync_test.cpp measures BML: the word after a
// sentence pause is heard as a new voiced stretch, whose onset (found by energy) must be within
// one frame of the first rendered frame where the intention's behaviour moves the face.
#include <gtest/gtest.h>

#include <cstdio>

#include "fapc/speech/engine.hpp"
#include "intent_test_support.hpp"
#include "support/voiced_segments.hpp"

namespace fapc {
namespace {

constexpr double kFrame = 1.0 / 25;

// The time of the frame before the first where FAP `fap` is away from 0.
double first_move(const FapSequence& frames, int fap) {
  for (const FapFrame& f : frames.frames)
    if (f.has(fap) && f.value(fap) != 0) return double(f.number - 1) / frames.fps;
  return -1;
}

void expect_synced(const std::string& name, const std::string& document, int fap, std::size_t stretch) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  Result<pipeline::Loaded> loaded = test::load_at_25(test::write_temp(name, document));
  ASSERT_TRUE(loaded) << loaded.error().message;
  ASSERT_TRUE(loaded->audio);
  std::vector<double> onsets;
  for (const test::Segment& s : test::voiced_segments(*loaded->audio, 0.1)) onsets.push_back(s.begin);
  ASSERT_GT(onsets.size(), stretch) << "the marked word should follow a pause";
  const double moved = first_move(loaded->frames, fap);
  std::printf("word onset %.3f s, intention's behaviour starts %.3f s\n", onsets[stretch], moved);
  EXPECT_NEAR(moved, onsets[stretch], kFrame + 0.01);
}

TEST(IntentSpeechSync, AnFmlApmlIntentionOnAMarkStartsWithTheMarkedWord) {
  // performative inform: a nod (head_pitch, FAP 48) from the span's start (data/intentions.tsv).
  expect_synced(
      "sync.xml",
      R"(<fml-apml><bml><speech id="s1"><tm id="tm1"/>Good morning to you. <tm id="tm2"/>Look at this.<tm id="tm3"/></speech></bml>
<fml><performative id="p1" type="inform" start="s1:tm2" end="s1:tm3" importance="1"/></fml></fml-apml>
)",
      48, 1);
}

TEST(IntentSpeechSync, AnApmlEmphasisStartsWithItsWord) {
  // emphasis: the brows rise (raise_l_i_eyebrow, FAP 31) from the span's start.
  expect_synced("sync-apml.xml",
                R"(<apml>Good morning to you. <emphasis x-pitchaccent="Hstar">Look</emphasis> at this.</apml>
)",
                31, 1);
}

}  // namespace
}  // namespace fapc

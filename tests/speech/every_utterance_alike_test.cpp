// Every utterance alike (docs/speech.md): the same text and voice give the same samples, phonemes
// and word times whatever the process said before. eSpeak NG 1.51 alone fails this (its wave
// generator's phase, pitch flutter and gain outlive an utterance: "Hello there, how are you
// today?" gave 36797 samples the first time and 37772 after "The quick brown fox ..."), so each
// case speaks A, then something else, then A again, and compares the two A's byte for byte.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "fapc/speech/engine.hpp"

namespace fapc {
namespace {

SpeechRequest said(std::string text, std::string language = "en", std::string voice = "") {
  SpeechRequest request;
  request.text = std::move(text);
  request.language = std::move(language);
  request.voice = std::move(voice);
  request.where = Location::text("alike.fml", 3, 5);
  return request;
}

Utterance spoken(const SpeechRequest& request) {
  Result<Utterance> out = speech::engine()(request);
  if (!out) ADD_FAILURE() << format_diagnostic(out.error());
  return out ? std::move(*out) : Utterance{};
}

// The samples as bytes, so that a difference is reported as one.
std::string bytes_of(const Utterance& u) {
  std::string out(u.audio.samples.size() * sizeof(std::int16_t), '\0');
  if (!out.empty()) std::memcpy(out.data(), u.audio.samples.data(), out.size());
  return out;
}

void expect_alike(const Utterance& first, const Utterance& again) {
  EXPECT_FALSE(first.audio.samples.empty());
  EXPECT_EQ(first.audio.samples.size(), again.audio.samples.size());
  EXPECT_TRUE(bytes_of(first) == bytes_of(again)) << "the same text gave other samples";
  EXPECT_TRUE(first.phonemes == again.phonemes) << "the same text gave other phonemes or phoneme times";
  EXPECT_TRUE(first.words == again.words) << "the same text gave other word times";
}

TEST(EveryUtteranceAlike, TheSameSentenceAfterAnother) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  const SpeechRequest a = said("Hello there, how are you today?");
  const Utterance first = spoken(a);
  spoken(said("The quick brown fox jumps over the lazy dog."));
  expect_alike(first, spoken(a));
  expect_alike(first, spoken(a));  // and right after itself
}

TEST(EveryUtteranceAlike, AfterOtherLanguagesVoicesAndRates) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  const SpeechRequest a = said("Bonjour, comment allez-vous?", "fr", "f3");
  const Utterance first = spoken(a);
  SpeechRequest fast = said("Schnell gesprochen, mit einer anderen Stimme.", "de", "m3");
  fast.words_per_minute = 300;
  spoken(fast);
  spoken(said("Hello.", "en-us"));
  expect_alike(first, spoken(a));
}

// The Klatt synthesiser and the breathy voices draw noise from rand(): its state in the
// speaking process must not matter either.
TEST(EveryUtteranceAlike, NoisyVoicesWhateverRandDid) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  for (const char* voice : {"klatt", "whisper"}) {
    SCOPED_TRACE(voice);
    const SpeechRequest a = said("She sells sea shells by the sea shore.", "en", voice);
    const Utterance first = spoken(a);
    std::srand(12345);
    for (int i = 0; i < 17; ++i) static_cast<void>(std::rand());
    spoken(said("Something else entirely.", "en", "m2"));
    expect_alike(first, spoken(a));
  }
}

}  // namespace
}  // namespace fapc

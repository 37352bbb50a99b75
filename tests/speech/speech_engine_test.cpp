// The engine and its table (docs/speech.md): phonemes with times that cover the audio, every
// phoneme the engine says in English, French and German has a viseme, the per-language entries,
// clear errors for unknown languages and voices, the letter-table fallback with its warning, and
// .wav output refused (not written empty) for an input without audio.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/engine.hpp"
#include "fapc/speech/phoneme_visemes.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

TEST(SpeechTable, VisemesOfTheEnginesMnemonics) {
  using speech::viseme_of_espeak_phoneme;
  // The MPEG-4 table's own examples (ISO/IEC 14496-2 viseme table), by eSpeak NG's names.
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "p"), 1);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "m"), 1);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "v"), 2);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "D"), 3);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "d"), 4);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "g"), 5);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "tS"), 6);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "z"), 7);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "l"), 8);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "r"), 9);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "A:"), 10);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "E"), 11);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "I"), 12);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "0"), 13);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "U"), 14);
  // Pauses and sounds without a mouth shape of their own.
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "_:"), 0);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "h"), 0);
  // Per language: eSpeak's "3" is ɜ in English, ɐ in German; "Y" is ø in French, ʏ in German.
  EXPECT_EQ(viseme_of_espeak_phoneme("en-us", "3"), 11);
  EXPECT_EQ(viseme_of_espeak_phoneme("de", "3"), 10);
  EXPECT_EQ(viseme_of_espeak_phoneme("fr", "Y"), 13);
  EXPECT_EQ(viseme_of_espeak_phoneme("de", "Y"), 14);
  // Variant marks fall back to the base sound; unknown names are -1.
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "l/"), 8);
  EXPECT_EQ(viseme_of_espeak_phoneme("en", "Q!"), -1);
}

TEST(SpeechEngine, EveryPhonemeOfThreeLanguagesHasAViseme) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  const std::pair<const char*, const char*> texts[] = {
      {"en",
       "The quick brown fox jumps over the lazy dog. She sells sea shells. How now brown cow? "
       "I thought the weather was rather pleasant, although the judge's vision was blurry. Boy, poor, "
       "tour, hair, near, cure, bird, father, cat, cot, caught, put, boot, butter, button, little."},
      {"en-us", "Water, butter, better, car, poor, tour, hair. Peter Piper picked a peck."},
      {"fr",
       "Portez ce vieux whisky au juge blond qui fume. Le cœur, deux œufs, la peur, une rue, huit, "
       "oui, fille, agneau, rouge, chat, gens, feu, neuf, thé, mère, tu, loup, champignon, brun."},
      {"de",
       "Victor jagt zwölf Boxkämpfer quer über den großen Sylter Deich. Ach, Pfeffer, Zeit, Mädchen, "
       "schön, Bücher, Hütte, Bäume, Leute, Haus, Stadt, ruhig, Ring, Vater, Obst, Uhr, Öl, lang."},
  };
  for (const auto& [language, text] : texts) {
    SpeechRequest request;
    request.text = text;
    request.language = language;
    Result<Utterance> spoken = speech::engine()(request);
    ASSERT_TRUE(spoken) << spoken.error().message;
    EXPECT_TRUE(spoken->warnings.empty()) << language << ": " << spoken->warnings.front().message;
    ASSERT_FALSE(spoken->phonemes.empty());
    EXPECT_GT(spoken->audio.samples.size(), 0u);
    EXPECT_NEAR(spoken->phonemes.back().end, spoken->duration, 1e-9);
    for (std::size_t i = 1; i < spoken->phonemes.size(); ++i)
      EXPECT_LE(spoken->phonemes[i - 1].begin, spoken->phonemes[i].begin);
  }
}

TEST(SpeechEngine, UnknownLanguageAndVoiceAreErrorsAtTheElement) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  SpeechRequest request;
  request.text = "Hi";
  request.where = Location::text("story.fml", 3, 7);
  request.language = "xx";
  Result<Utterance> spoken = speech::engine()(request);
  ASSERT_FALSE(spoken);
  EXPECT_EQ(spoken.error().kind, ErrorKind::bad_input);
  EXPECT_EQ(spoken.error().where.line, 3);
  request.language = "en";
  request.voice = "nosuch";
  spoken = speech::engine()(request);
  ASSERT_FALSE(spoken);
  EXPECT_EQ(spoken.error().where.column, 7);
  request.voice = "../../etc";
  EXPECT_FALSE(speech::engine()(request));
}

TEST(SpeechEngine, ThreadsAreSerialised) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  SpeechRequest en;
  en.text = "Hello there, how are you?";
  SpeechRequest fr = en;
  fr.language = "fr";
  fr.text = "Bonjour, comment allez-vous ?";
  const Result<Utterance> alone_en = speech::engine()(en);
  const Result<Utterance> alone_fr = speech::engine()(fr);
  ASSERT_TRUE(alone_en && alone_fr);
  std::vector<std::thread> threads;
  std::vector<int> same(8, 0);  // not vector<bool>: threads write neighbouring elements
  for (int i = 0; i < 8; ++i) {
    threads.emplace_back([&, i] {
      const Result<Utterance> again = speech::engine()(i % 2 ? fr : en);
      // Every utterance starts from the same engine state (docs/speech.md, "Every utterance
      // alike"): the very samples and phonemes of the lone call, none mixed with another thread's.
      const Utterance& alone = *(i % 2 ? alone_fr : alone_en);
      same[static_cast<std::size_t>(i)] =
          again && again->audio.samples == alone.audio.samples && again->phonemes == alone.phonemes;
    });
  }
  for (std::thread& t : threads) t.join();
  for (int i = 0; i < 8; ++i) EXPECT_TRUE(same[static_cast<std::size_t>(i)]) << i;
}

std::string write_file(const std::string& name, const std::string& text) {
  const fs::path dir = test::scratch_folder("speech-engine-test");
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

TEST(SpeechFallback, WithoutTheEngineTheLetterTableWarns) {
  const std::string path = write_file("fallback.fml", "<fml><story><talk>Hello</talk></story></fml>\n");
  pipeline::ConvertOptions options;
  options.speech_engine = false;
  Result<pipeline::Loaded> loaded = pipeline::load(path, options);
  ASSERT_TRUE(loaded) << loaded.error().message;
  EXPECT_FALSE(loaded->audio);
  ASSERT_EQ(loaded->warnings.size(), 1u);
  EXPECT_EQ(loaded->warnings[0].severity, Severity::warning);
  EXPECT_EQ(loaded->warnings[0].where.line, 1);
  EXPECT_EQ(loaded->warnings[0].where.column, 13);
  // The letter table at 175 words per minute: 12 visemes per second, "Hello" is E, nn, oh.
  ASSERT_TRUE(loaded->timeline);
  EXPECT_NEAR(loaded->timeline->end(), 0.25 + 0.03, 1e-9);  // the last viseme's fade to neutral
}

TEST(SpeechWav, NoAudioIsAnErrorAndNoFile) {
  const std::string input = test::corpus_dir() + "/examples/fap/joy.fap";
  const std::string output =
      (fs::temp_directory_path() / ("fapc-no-audio-" + std::to_string(::getpid()) + ".wav")).string();
  pipeline::ConvertResult result =
      pipeline::convert(input, {pipeline::OutputRequest{output, ""}}, pipeline::ConvertOptions{});
  EXPECT_FALSE(result.ok());
  EXPECT_FALSE(fs::exists(output));
}

}  // namespace
}  // namespace fapc

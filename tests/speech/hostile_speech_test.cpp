// Hostile speech and audio (issue 32, docs/security.md): talk text that crashed eSpeak NG 1.51,
// MBROLA voices that made it run a program found on the PATH, talk text and speech too long for
// the policy (refused before synthesis, named with its option), and audio tracks sized by the
// timeline (checked against --max-audio-samples before anything is allocated).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/engine.hpp"
#include "fapc/speech/speakable_text.hpp"
#include "fapc/transcoder/audio_mix.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

fs::path scratch() { return test::scratch_folder("hostile-speech"); }

std::string write_file(const std::string& name, const std::string& text) {
  const fs::path path = scratch() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

std::string repeated(const std::string& piece, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += piece;
  return out;
}

TEST(SpeakableText, NeutralisesTheShapesThatCrashTheEngine) {
  using speech::speakable_text;
  // Runs of one punctuation mark become one ('.' up to three); spaces and controls collapse.
  EXPECT_EQ(speakable_text("---\xE0\xA4\xB2"), "-\xE0\xA4\xB2");
  EXPECT_EQ(speakable_text("wait.....  what?!!\t\x01 no"), "wait... what?! no");
  // Stacked suffixes: a word is broken every kMaxWordBytes bytes, never inside a character.
  const std::string shaped = speakable_text(repeated("s'", 100));
  std::size_t word = 0;
  for (const char c : shaped) {
    word = c == ' ' ? 0 : word + 1;
    EXPECT_LE(word, speech::kMaxWordBytes);
  }
  const std::string long_word = speakable_text(repeated("\xC3\xA9", 100));  // é, 2 bytes each
  for (std::size_t i = 0; i < long_word.size(); ++i) {
    if (long_word[i] == ' ') {
      EXPECT_EQ(static_cast<unsigned char>(long_word[i + 1]), 0xC3);
    }
  }
  // Unassigned code points (U+058B, U+058C), surrogates, overlong forms and stray bytes become spaces.
  EXPECT_EQ(speakable_text("a\xD6\x8C\xD8\x8C b"), "a \xD8\x8C b");
  EXPECT_EQ(speakable_text("x\xD6\x8By"), "x y");
  EXPECT_EQ(speakable_text("x\xED\xA0\x80y\xC0\xAFz\xFFw\x80v"), "x y z w v");
  // Honest text is left as it was, in any script.
  EXPECT_EQ(speakable_text("Peter bought a map. Was it 3.5 km - or more?"),
            "Peter bought a map. Was it 3.5 km - or more?");
  EXPECT_EQ(speakable_text(
                "\xD5\xA2\xD5\xA1\xD6\x80\xD6\x87 \xD9\x85\xD8\xB1\xD8\xAD\xD8\xA8\xD8\xA7\xD8\x8C \xF0\x9F\x98\x80"),
            "\xD5\xA2\xD5\xA1\xD6\x80\xD6\x87 \xD9\x85\xD8\xB1\xD8\xAD\xD8\xA8\xD8\xA7\xD8\x8C \xF0\x9F\x98\x80");
}

TEST(SpeakableText, PiecesAreBoundedAndEndAtSentences) {
  std::string text;
  for (int i = 0; i < 200; ++i) text += "Sentence number " + std::to_string(i) + " is here. ";
  const std::vector<std::string> pieces = speech::speakable_pieces(text);
  ASSERT_GT(pieces.size(), 5u);
  std::string joined;
  for (const std::string& piece : pieces) {
    EXPECT_LE(piece.size(), speech::kMaxPieceBytes);
    EXPECT_EQ(piece.back(), '.');
    joined += (joined.empty() ? "" : " ") + piece;
  }
  EXPECT_EQ(joined, speech::speakable_text(text));
  // No space at all: cut at character boundaries.
  for (const std::string& piece : speech::speakable_pieces(repeated("ab", 2000)))
    EXPECT_LE(piece.size(), speech::kMaxPieceBytes);
}

// Each of these aborted or crashed eSpeak NG 1.51 (and so the whole process) before the text was
// shaped: 70 stacked English suffixes overflow a 200-byte buffer ("buffer overflow detected"),
// three hyphens before a Devanagari word make the Hindi voice read before its phoneme list.
TEST(SpeechEngine, TextThatCrashedTheEngineIsSpoken) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  const std::pair<const char*, std::string> texts[] = {
      {"en", repeated("s'", 100)},
      {"en", repeated("s'", 220)},
      {"hi", "---\xE0\xA4\xB2\xE0\xA4\x9A\xE0\xA5\x8D\xE0\xA4\x9B\xE0\xA5\x87\xE0\xA4\xA6"},
      {"en", repeated("-", 20000)},
      // An unassigned Armenian code point before Arabic punctuation: a use after free inside the
      // engine (its language switch frees the dictionary it reads next; found by fuzzing).
      {"en", "\xD6\x8C\xD8\x8C"},
      {"en", "a-'s's'ss\xD6\x8B\xD8\x9B-b"},
  };
  for (const auto& [language, text] : texts) {
    SpeechRequest request;
    request.language = language;
    request.text = text;
    const Result<Utterance> spoken = speech::engine()(request);
    EXPECT_TRUE(spoken) << language << ": " << (spoken ? "" : spoken.error().message);
  }
}

TEST(SpeechEngine, LongTextIsSpokenInPiecesWithPhonemesOnOneClock) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  SpeechRequest request;
  for (int i = 0; i < 60; ++i) request.text += "The quick brown fox jumps over the lazy dog. ";
  ASSERT_GT(request.text.size(), 2 * speech::kMaxPieceBytes);
  const Result<Utterance> spoken = speech::engine()(request);
  ASSERT_TRUE(spoken) << spoken.error().message;
  ASSERT_FALSE(spoken->phonemes.empty());
  for (std::size_t i = 1; i < spoken->phonemes.size(); ++i)
    EXPECT_LE(spoken->phonemes[i - 1].begin, spoken->phonemes[i].begin) << i;
  // The last piece's phonemes end with the audio: the pieces' clocks were joined.
  EXPECT_NEAR(spoken->phonemes.back().end, spoken->duration, 1e-9);
  EXPECT_GT(spoken->phonemes.back().begin, spoken->duration - 1.0);
  EXPECT_GT(spoken->duration, 60 * 2.0);
}

// An MBROLA voice made eSpeak NG fork the first `mbrola` on the PATH: a script chose a program
// to run. A fake one that leaves a mark shows that nothing is run, and the engine prints nothing.
TEST(SpeechEngine, MbrolaVoicesAreRefusedAndRunNothing) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  const fs::path bin = scratch() / "bin";
  fs::create_directories(bin);
  const fs::path mark = scratch() / "mbrola-ran";
  fs::remove(mark);
  write_file("bin/mbrola", "#!/bin/sh\ntouch '" + mark.string() + "'\nexit 1\n");
  fs::permissions(bin / "mbrola", fs::perms::owner_all);
  for (const std::string lang : {"mb-en1", "MB-fr1", "mb-de2"}) {
    const std::string fml =
        write_file("mbrola.fml", "<fml><story><talk lang=\"" + lang + "\">Hello</talk></story></fml>\n");
    const fs::path out = scratch() / "mbrola.wav";
    const test::CommandRun run = test::run_shell("PATH='" + bin.string() + "':$PATH '" + test::fapc_program() +
                                                 "' compile '" + fml + "' -o '" + out.string() + "'");
    EXPECT_EQ(run.exit_status, 1) << lang;
    EXPECT_NE(run.err.find("mbrola.fml:1:"), std::string::npos) << run.err;  // at the talk's lang
    EXPECT_NE(run.err.find("error: '" + lang + "' is an MBROLA voice"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("mbrowrap"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(mark)) << lang << " ran the mbrola program";
  }
}

pipeline::ConvertResult convert_to(const std::string& input, const std::string& output,
                                   const pipeline::ConvertOptions& options) {
  fs::remove(output);
  return pipeline::convert(input, {pipeline::OutputRequest{output, ""}}, options);
}

TEST(SpeechLimits, TalkTextBeyondTheLimitIsRefusedAtTheTalkBeforeSynthesis) {
  const std::string text = repeated("Hello there. ", 6000);  // 78,000 bytes
  const std::string fml = write_file("long.fml", "<fml><story>\n  <talk>" + text + "</talk></story></fml>\n");
  const auto started = std::chrono::steady_clock::now();
  const pipeline::ConvertResult result = convert_to(fml, (scratch() / "long.wav").string(), {});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error->kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(result.error->where.line, 2);
  EXPECT_EQ(result.error->where.column, 3);
  EXPECT_NE(result.error->message.find("--max-speech-text"), std::string::npos) << result.error->message;
  EXPECT_LT(seconds, 2.0);  // nothing was synthesised (the text takes some 15 s to say... and 60 s of audio)
  EXPECT_FALSE(fs::exists(scratch() / "long.wav"));
}

// The conversion failed on the speech-seconds limit, naming its option and saying `how`.
void expect_speech_seconds_refused(const pipeline::ConvertResult& result, const std::string& how) {
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error->kind, ErrorKind::limit_exceeded);
  EXPECT_NE(result.error->message.find(how), std::string::npos) << result.error->message;
  EXPECT_NE(result.error->message.find("(--max-speech-seconds N raises it)"), std::string::npos)
      << result.error->message;
}

TEST(SpeechLimits, SpeechEstimatedLongerThanTheLimitIsRefusedBeforeSynthesis) {
  pipeline::ConvertOptions options;
  options.limits.max_speech_seconds = 60;
  // 4,000 letters: at least 167 s at the fastest honest rate; 200 short talks the same.
  for (const std::string& story : {"<talk>" + repeated("Hello there. ", 400) + "</talk>",
                                   "<seq>" + repeated("<talk>Hello there</talk>", 400) + "</seq>"}) {
    const std::string fml = write_file("estimate.fml", "<fml><story>" + story + "</story></fml>\n");
    expect_speech_seconds_refused(convert_to(fml, (scratch() / "estimate.wav").string(), options), "at least");
  }
}

TEST(SpeechLimits, TalksRepeatedByATemplateCountAsTheyAreSpoken) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  pipeline::ConvertOptions options;
  options.limits.max_speech_seconds = 20;
  // One talk in the text, spoken 100 times (about 0.8 s each): only the reader's count sees it.
  const std::string fml = write_file(
      "many.fml", "<fml><model><template name=\"t\"><talk>Hello there</talk></template></model><story><seq>" +
                      repeated("<behavior name=\"t\"/>", 100) + "</seq></story></fml>\n");
  expect_speech_seconds_refused(convert_to(fml, (scratch() / "many.wav").string(), options), "speech of this document");
  options.limits.max_speech_seconds = 1000;
  const pipeline::ConvertResult spoken = convert_to(fml, (scratch() / "many.wav").string(), options);
  EXPECT_TRUE(spoken.ok()) << (spoken.ok() ? "" : spoken.error->message);
}

AudioClip tone(double begin, int rate, std::size_t count, std::int16_t value, int line) {
  AudioClip clip;
  clip.begin = begin;
  clip.sample_rate = rate;
  clip.samples.assign(count, value);
  clip.source = Location::text("a.xmt", line, 5);
  return clip;
}

TEST(AudioLimits, MixingRatesOrFarApartClipsIsCheckedBeforeAllocating) {
  // 1,000 s of a 1 Hz recording mixed at the 384 kHz of the other: 384 million samples.
  const std::vector<AudioClip> rates = {tone(0, 384000, 10, 100, 3), tone(0, 1, 1000, 100, 4)};
  Result<std::optional<AudioTrack>> mixed = mix_audio(rates, 1e9);
  ASSERT_FALSE(mixed);
  EXPECT_EQ(mixed.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(mixed.error().where.line, 4);  // the clip that reaches furthest
  EXPECT_NE(mixed.error().message.find("(--max-audio-samples N raises it)"), std::string::npos)
      << mixed.error().message;
  // Two clips 40,000 s apart at 22,050 Hz.
  const std::vector<AudioClip> apart = {tone(0, 22050, 100, 100, 3), tone(40000, 22050, 100, 100, 7)};
  mixed = mix_audio(apart, 1e9);
  ASSERT_FALSE(mixed);
  EXPECT_EQ(mixed.error().where.line, 7);
  Limits raised;
  raised.max_audio_samples = std::int64_t{1} << 30;
  EXPECT_TRUE(mix_audio({tone(0, 8000, 100, 100, 3), tone(3000, 8000, 100, 100, 7)}, 1e9, raised));
}

TEST(AudioLimits, TheBlockwiseMixSumsAndSaturatesAcrossBlocks) {
  // Two loud clips overlapping across several 65,536-sample blocks, a quiet one far after.
  const std::vector<AudioClip> clips = {tone(0, 22050, 200000, 20000, 1), tone(1, 22050, 200000, 20000, 2),
                                        tone(30, 11025, 10, -300, 3)};
  Result<std::optional<AudioTrack>> mixed = mix_audio(clips, 1e9);
  ASSERT_TRUE(mixed && *mixed);
  const AudioTrack& track = **mixed;
  ASSERT_EQ(track.sample_rate, 22050);
  EXPECT_EQ(track.samples.size(), 30u * 22050 + 20);
  EXPECT_EQ(track.samples[0], 20000);
  EXPECT_EQ(track.samples[22049], 20000);
  for (std::size_t n : {22050u, 65535u, 65536u, 131072u, 199999u}) EXPECT_EQ(track.samples[n], 32767) << n;
  EXPECT_EQ(track.samples[200000], 20000);
  EXPECT_EQ(track.samples[222049], 20000);
  EXPECT_EQ(track.samples[222050], 0);
  EXPECT_EQ(track.samples[30u * 22050 + 1], -300);  // the 11,025 Hz clip, resampled: one value throughout
}

TEST(AudioLimits, ALateTalkToWavIsRefusedUpFront) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  // 40,000 s of silence before the voice: 882 million samples in the .wav. The frames fit at 1 fps.
  const std::string fml = write_file("late.fml", "<fml><story><talk begin=\"40000\">Hi</talk></story></fml>\n");
  pipeline::ConvertOptions options;
  options.fps = 1;
  const std::string out = (scratch() / "late.wav").string();
  const pipeline::ConvertResult result = convert_to(fml, out, options);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error->kind, ErrorKind::limit_exceeded);
  EXPECT_NE(result.error->message.find("(--max-audio-samples N raises it)"), std::string::npos)
      << result.error->message;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace fapc

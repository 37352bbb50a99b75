// SmartBody / NVBG BML (docs/bml.md, "SmartBody"): recorded speech takes its mark times from the
// document and its voice from the WAV beside it, never from synthesis; <lips> rows move the mouth
// through smartbody_visemes.tsv; face type="facs" and head type= take the BML 1.0 paths. The
// documents are written here in the corpus files' style; the WAV is made by the test.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "bml/smartbody_visemes.hpp"
#include "fapc/bml/bml.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/codes.hpp"
#include "fapc/transcoder/wav.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "support/sync_to_word.hpp"
#include "support/test_support.hpp"

namespace fapc::bml {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() { return test::scratch_folder("bml-smartbody"); }

// NVBG's output: placeholder speech times (end="0.2" for 1.24 s of words), marks with their
// recorded times, the audio by its stem, one lips row per viseme, FaceFX curves.
const char* kRecorded = R"(<?xml version="1.0" encoding="utf-8"?>
<bml>
    <speech id="sp1" start="0.0" ready="0.1" stroke="0.1" relax="0.2" end="0.2">
        <text>
            <sync id="T0" time="0" />we
            <sync id="T1" time="0.09" />
            <sync id="T2" time="0.34" />take
            <sync id="T3" time="0.58" />
            <sync id="T4" time="0.66" />temperature
            <sync id="T5" time="1.24" />
        </text>
        <description level="1" type="audio/x-wav">
            <file ref="take" />
        </description>
    </speech>
    <lips viseme="W" articulation="1.0" start="0" ready="0" relax="0.09" end="0.09" />
    <lips viseme="BMP" articulation="1.0" start="0.2" ready="0.2" relax="0.4" end="0.4" />
    <lips viseme="Aa" articulation="0.5" start="0.6" ready="0.6" relax="1.0" end="1.0" />
    <head id="n1" type="NOD" start="sp1:T2" />
    <face id="f1" type="facs" au="1" amount="1" start="sp1:T4" end="1.24" />
    <curves>
        <curve name="BMP" num_keys="3" owner="analysis">0 0 0 0 0.3 1 0 0 0.5 0 0 0</curve>
    </curves>
</bml>
)";

std::string write(const std::string& name, const std::string& text) {
  const fs::path path = temp_dir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

// 1.5 s of a 200 Hz tone at 16 kHz: the recording.
AudioTrack tone() {
  AudioTrack track;
  track.sample_rate = 16000;
  for (int i = 0; i < 24000; ++i)
    track.samples.push_back(static_cast<std::int16_t>(8000 * std::sin(2 * std::numbers::pi * 200 * i / 16000.0)));
  return track;
}

int count(const Diagnostics& warnings, const std::string& code) {
  int n = 0;
  for (const Diagnostic& w : warnings) n += w.code == code ? 1 : 0;
  return n;
}

const Diagnostic* find(const Diagnostics& warnings, const std::string& code) {
  for (const Diagnostic& w : warnings)
    if (w.code == code) return &w;
  return nullptr;
}

// Options whose speech engine fails the test if it is ever asked to speak.
ReaderOptions no_synthesis(int& calls) {
  ReaderOptions options;
  options.speech.synthesize = [&calls](const SpeechRequest&) -> Result<Utterance> {
    ++calls;
    return make_error(codes::speech::engine_failed, Location{}, "recorded speech must not be synthesised");
  };
  return options;
}

TEST(BmlSmartBody, MarksLandAtTheirRecordedTimesAndTheRecordingWinsOverPlaceholders) {
  fs::remove(temp_dir() / "take.wav");
  int calls = 0;
  const Result<BmlDocument> d = load_bml(write("marks.bml", kRecorded), no_synthesis(calls));
  ASSERT_TRUE(d) << format_diagnostic(d.error());
  EXPECT_EQ(calls, 0) << "the engine was asked to speak recorded speech";
  EXPECT_EQ(d->dialect, "SmartBody");
  std::map<std::string, double> marks;
  for (const ScheduledMark& m : d->marks) marks[m.id] = m.time;
  EXPECT_DOUBLE_EQ(marks["T2"], 0.34);
  EXPECT_DOUBLE_EQ(marks["T4"], 0.66);
  for (const ScheduledBehaviour& b : d->behaviours) {
    if (b.id == "sp1") {
      EXPECT_DOUBLE_EQ(b.end, 1.24);  // the last mark: no audio here
    } else if (b.id == "n1") {
      EXPECT_DOUBLE_EQ(b.start, 0.34);
    } else if (b.id == "f1") {
      EXPECT_DOUBLE_EQ(b.start, 0.66);
    } else if (b.element == "curves") {  // from its first key to its last
      EXPECT_DOUBLE_EQ(b.start, 0);
      EXPECT_DOUBLE_EQ(b.end, 0.5);
    }
  }
  // The placeholders are said once, at the first that disagrees (ready="0.1", line 3).
  ASSERT_EQ(count(d->warnings, "bml.recorded_timing_wins"), 1);
  const Diagnostic* placeholder = find(d->warnings, "bml.recorded_timing_wins");
  EXPECT_EQ(placeholder->where.line, 3);
  EXPECT_EQ(placeholder->where.column, 34);  // ready=
  // No WAV beside the document: said at the file element, and no voice.
  const Diagnostic* missing = find(d->warnings, "bml.recorded_audio_missing");
  ASSERT_NE(missing, nullptr);
  EXPECT_EQ(missing->where.line, 13);
  EXPECT_TRUE(d->timeline.audio.empty());
  EXPECT_EQ(count(d->warnings, "bml.not_drawn"), 1);  // curves, once
}

TEST(BmlSmartBody, TheRecordingBesideTheDocumentIsTheVoice) {
  const std::string wav = write("take.wav", wav_bytes(tone()));
  int calls = 0;
  const Result<BmlDocument> d = load_bml(write("voiced.bml", kRecorded), no_synthesis(calls));
  ASSERT_TRUE(d) << format_diagnostic(d.error());
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(count(d->warnings, "bml.recorded_audio_missing"), 0);
  ASSERT_EQ(d->timeline.audio.size(), 1U);
  EXPECT_EQ(d->timeline.audio[0].samples, tone().samples);
  EXPECT_DOUBLE_EQ(d->timeline.audio[0].begin, 0);
  ASSERT_EQ(d->recordings.size(), 1U);
  for (const ScheduledBehaviour& b : d->behaviours)
    if (b.id == "sp1") {
      EXPECT_DOUBLE_EQ(b.end, 1.5);  // the audio outlasts the last mark
    }

  // Through the pipeline: the frames' sound is the recording, from time 0.
  pipeline::ConvertOptions options;
  options.fps = 25;
  options.speech_engine = false;
  const Result<pipeline::Loaded> loaded = pipeline::load((temp_dir() / "voiced.bml").string(), options);
  ASSERT_TRUE(loaded) << format_diagnostic(loaded.error());
  ASSERT_TRUE(loaded->audio.has_value());
  ASSERT_GE(loaded->audio->samples.size(), 24000U);
  const double rate = loaded->audio->sample_rate;
  double energy = 0;
  for (std::size_t i = 0; i < static_cast<std::size_t>(rate); ++i)
    energy += std::abs(double(loaded->audio->samples[i]));
  EXPECT_GT(energy / rate, 3000);  // the tone's mean level is 8000 * 2/pi

  // In an .mp4: its sound track, read back, is the tone (AAC keeps its level within a few %).
  const std::string mp4 = (temp_dir() / "voiced.mp4").string();
  const pipeline::ConvertResult written = pipeline::convert((temp_dir() / "voiced.bml").string(), {{mp4, ""}}, options);
  ASSERT_TRUE(written.ok()) << written.error->message;
  const Result<pipeline::Loaded> back = pipeline::load(mp4, options);
  ASSERT_TRUE(back) << format_diagnostic(back.error());
  ASSERT_TRUE(back->audio.has_value());
  double square = 0;
  for (std::int16_t v : back->audio->samples) square += double(v) * v;
  const double rms = std::sqrt(square / double(back->audio->samples.size()));
  EXPECT_NEAR(rms, 8000 / std::numbers::sqrt2, 800) << "the tone's level is 8000 / sqrt 2";
  fs::remove(mp4);
  fs::remove(wav);
}

// Measured on the audio as the speech sync tests do: a recording of two words (tones after
// silences), marks at their onsets, a nod synced to the second word's mark starts within one frame
// of where that word is heard.
TEST(BmlSmartBody, ANodSyncedToARecordedMarkStartsWithTheWordInTheAudio) {
  AudioTrack words;
  words.sample_rate = 16000;
  for (int i = 0; i < 24000; ++i) {
    const double t = i / 16000.0;
    const bool voiced = (t >= 0.3 && t < 0.6) || (t >= 1.0 && t < 1.4);
    words.samples.push_back(static_cast<std::int16_t>(voiced ? 8000 * std::sin(2 * std::numbers::pi * 180 * t) : 0));
  }
  write("two.wav", wav_bytes(words));
  test::expect_moves_with_word(write("two.bml", R"(<bml>
<speech id="sp1" start="0.0" end="0.2"><text><sync id="T0" time="0.3"/>good <sync id="T1" time="0.6"/>
<sync id="T2" time="1.0"/>morning<sync id="T3" time="1.4"/></text>
<description level="1" type="audio/x-wav"><file ref="two"/></description></speech>
<head id="n1" type="NOD" start="sp1:T2"/>
</bml>
)"),
                               48, 1);
}

TEST(BmlSmartBody, ARecordingIsBoundedAndMustBeAWav) {
  const std::string wav = write("take.wav", wav_bytes(tone()));
  ReaderOptions options;
  options.limits.max_decompressed_bytes = 1000;  // the tone is 48 KB
  const Result<BmlDocument> big = load_bml(write("big.bml", kRecorded), options);
  ASSERT_FALSE(big);
  EXPECT_EQ(big.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(big.error().where.line, 13);
  options.limits = Limits{};
  options.limits.max_audio_samples = 1000;
  const Result<BmlDocument> long_one = load_bml(write("long.bml", kRecorded), options);
  ASSERT_FALSE(long_one);
  EXPECT_EQ(long_one.error().kind, ErrorKind::limit_exceeded);
  write("take.wav", "not a wav at all");
  const Result<BmlDocument> bad = load_bml(write("bad.bml", kRecorded), ReaderOptions{});
  ASSERT_FALSE(bad);
  // The include rules: a name leading outside the document's folder is refused.
  std::string outside = kRecorded;
  outside.replace(outside.find("ref=\"take\""), 10, "ref=\"../../etc/passwd\"");
  const Result<BmlDocument> escaped = load_bml(write("outside.bml", outside), ReaderOptions{});
  ASSERT_FALSE(escaped);
  EXPECT_NE(escaped.error().message.find("--allow-include"), std::string::npos) << escaped.error().message;
  fs::remove(wav);
}

// FAP 1 at the middle of each lips row: its viseme at its articulation.
TEST(BmlSmartBody, LipsMoveTheMouth) {
  fs::remove(temp_dir() / "take.wav");
  pipeline::ConvertOptions options;
  options.fps = 25;
  options.speech_engine = false;
  const Result<pipeline::Loaded> loaded = pipeline::load(write("lips.bml", kRecorded), options);
  ASSERT_TRUE(loaded) << format_diagnostic(loaded.error());
  const auto& frames = loaded->frames.frames;
  auto at = [&](double seconds) -> const FapFrame& {
    return frames.at(static_cast<std::size_t>(std::lround(seconds * 25)));
  };
  auto strength = [](const FapFrame& f, int viseme) {
    if (!f.has(1)) return 0;
    if (f.viseme.select1 == viseme) return f.viseme.blend;
    if (f.viseme.select2 == viseme) return 63 - f.viseme.blend;
    return 0;
  };
  EXPECT_EQ(strength(at(0.04), 14), 63);      // W: U, at full articulation
  EXPECT_EQ(strength(at(0.32), 1), 63);       // BMP: p/b/m
  EXPECT_NEAR(strength(at(0.8), 10), 32, 1);  // Aa at articulation 0.5: A:, half
  EXPECT_EQ(strength(at(0.48), 1), 0);        // between rows the mouth rests
}

TEST(BmlSmartBody, AnUnknownVisemeIsSaidWhereItStands) {
  const Result<BmlDocument> d = read_bml("<bml>\n<lips viseme=\"Qq\" start=\"0\" end=\"0.1\"/>\n</bml>", "u.bml");
  ASSERT_TRUE(d) << format_diagnostic(d.error());
  const Diagnostic* w = find(d->warnings, "bml.unknown_viseme");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->where.line, 2);
  EXPECT_TRUE(d->timeline.clips.empty());
}

TEST(BmlSmartBody, LipsWinOverSynthesisedVisemes) {
  // Without an engine the letter table gives the speech visemes: the lips row replaces them.
  const Result<BmlDocument> d = read_bml(R"(<bml><speech id="s"><text>hello there</text></speech>
<lips viseme="BMP" start="0" end="0.5"/></bml>)",
                                         "w.bml");
  ASSERT_TRUE(d) << format_diagnostic(d.error());
  EXPECT_EQ(count(d->warnings, "bml.lips_over_synthesis"), 1);
  ASSERT_EQ(d->timeline.clips.size(), 1U);
  EXPECT_EQ(std::string(d->timeline.clips[0].target), "viseme.PP");
}

TEST(BmlSmartBody, RecordedSpeechWithoutLipsSaysItsMouthIsStill) {
  const Result<BmlDocument> d =
      read_bml(R"(<bml><speech id="s"><text><sync id="a" time="0"/>hi<sync id="b" time="0.4"/><emph>there</emph></text>
<description type="audio/x-wav"><file ref="absent"/></description></speech></bml>)",
               (temp_dir() / "q.bml").string());
  ASSERT_TRUE(d) << format_diagnostic(d.error());
  EXPECT_EQ(count(d->warnings, "bml.recorded_speech_without_lips"), 1);
  EXPECT_EQ(count(d->warnings, "bml.recorded_timing_wins"), 0);   // no placeholders here
  EXPECT_EQ(count(d->warnings, "bml.speech_markup_skipped"), 1);  // emph: the recording is what is heard
}

TEST(BmlSmartBody, RecordedMarksOutOfOrderOrWithoutTimeAreErrors) {
  const std::string head = "<bml><speech id=\"s\"><text>";
  const std::string tail = "</text><description type=\"audio/x-wav\"><file ref=\"x\"/></description></speech></bml>";
  const Result<BmlDocument> back =
      read_bml(head + "<sync id=\"a\" time=\"0.5\"/>hi<sync id=\"b\" time=\"0.2\"/>" + tail, "o.bml");
  ASSERT_FALSE(back);
  EXPECT_NE(back.error().message.find("comes before the mark before it"), std::string::npos) << back.error().message;
  const Result<BmlDocument> untimed = read_bml(head + "<sync id=\"a\"/>hi" + tail, "o.bml");
  ASSERT_FALSE(untimed);
  EXPECT_NE(untimed.error().message.find("needs time"), std::string::npos);
  // A mark beyond the longest speech is refused before anything is scheduled or rendered.
  const Result<BmlDocument> far = read_bml(head + "<sync id=\"a\" time=\"1e300\"/>hi" + tail, "o.bml");
  ASSERT_FALSE(far);
  EXPECT_EQ(far.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(far.error().where.line, 1);
}

TEST(BmlSmartBody, FacsFaceAndTypedHeadTakeTheBml10Paths) {
  const Result<BmlDocument> smartbody =
      read_bml(R"(<bml><face id="f" type="facs" au="12" amount="0.5" start="0" end="2"/>
<head id="h" type="NOD" start="0"/></bml>)",
               "f.bml");
  const Result<BmlDocument> bml10 = read_bml(R"(<bml><faceFacs id="f" au="12" amount="0.5" start="0" end="2"/>
<head id="h" lexeme="NOD" start="0"/></bml>)",
                                             "f.bml");
  ASSERT_TRUE(smartbody) << format_diagnostic(smartbody.error());
  ASSERT_TRUE(bml10);
  ASSERT_EQ(smartbody->timeline.clips.size(), bml10->timeline.clips.size());
  ASSERT_GT(smartbody->timeline.clips.size(), 1U);
  for (std::size_t i = 0; i < bml10->timeline.clips.size(); ++i) {
    EXPECT_EQ(std::string(smartbody->timeline.clips[i].target), std::string(bml10->timeline.clips[i].target));
    EXPECT_EQ(smartbody->timeline.clips[i].curve.keys.size(), bml10->timeline.clips[i].curve.keys.size());
  }
}

// Every row: a name, a viseme 0..14, a reason; every viseme name of the corpus files is a row.
TEST(BmlSmartBody, TheVisemeTableIsWellFormed) {
  std::istringstream text{std::string(vocabulary::bundled_table_text("smartbody_visemes.tsv"))};
  std::string line;
  int rows = 0;
  while (std::getline(text, line)) {
    if (line.empty() || line[0] == '#' || line.starts_with("smartbody\t")) continue;
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, '\t');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 3U) << line;
    const int viseme = std::stoi(cells[1]);
    EXPECT_TRUE(viseme >= 0 && viseme <= 14) << line;
    EXPECT_GT(cells[2].size(), 10U) << line;
    EXPECT_EQ(smartbody_viseme(cells[0]), viseme);
    ++rows;
  }
  EXPECT_EQ(rows, static_cast<int>(smartbody_viseme_names().size()));
  for (const char* name :
       {"_", "Aa", "Ah", "BMP", "D", "Eh", "Er", "F", "H", "Ih", "Kg", "L", "Ow", "R", "Sh", "Th", "W", "Z"})
    EXPECT_TRUE(smartbody_viseme(name).has_value()) << name;
}

}  // namespace
}  // namespace fapc::bml

// `audio src="x.wav"`: the recording placed at the element's begin, its length the WAV's (cut by
// dur or clipEnd), the visemes of the .pho beside it timed with it; errors at the element.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fapc/transcoder/wav.hpp"
#include "support/test_support.hpp"
#include "xmto_test_helpers.hpp"

namespace fapc::xmt {
namespace {

namespace fs = std::filesystem;

const std::string kRecording = "/xmto/recording.xmt";

AudioClip fixture_wav() {
  const std::string path = fapc::test::corpus_dir() + "/xmto/recording/mama.wav";
  auto clip = read_wav(fapc::test::read_text(path), path);
  EXPECT_TRUE(clip.ok());
  return clip.ok() ? *clip : AudioClip{};
}

TEST(XmtoAudio, TheRecordingIsPlacedAtTheElementsBegin) {
  const auto doc = load_xmto(fapc::test::corpus_dir() + kRecording);
  ASSERT_TRUE(doc.ok()) << format_diagnostic(doc.error());
  const AudioClip wav = fixture_wav();
  ASSERT_EQ(doc->timeline.audio.size(), 1u);
  const AudioClip& placed = doc->timeline.audio[0];
  EXPECT_EQ(placed.begin, 1.0);
  EXPECT_EQ(placed.sample_rate, wav.sample_rate);
  EXPECT_EQ(placed.samples, wav.samples);
  EXPECT_EQ(placed.source.line, 7);
  EXPECT_EQ(placed.source.file, fapc::test::corpus_dir() + kRecording);
  // The .pho was read and both files are named as the document's inputs.
  ASSERT_EQ(doc->included.size(), 2u);
  EXPECT_TRUE(doc->included[0].ends_with("mama.wav"));
  EXPECT_TRUE(doc->included[1].ends_with("mama.pho"));
}

// mama.pho: _ 20, m 80, a 60, m 80, a 80 (ms): m at [0.02, 0.10) and [0.16, 0.24) from the
// recording's start, which is 1 s. With the 60 ms cross-fades of docs/speech.md PP (closed lips)
// is at full weight over [0.04, 0.07] and [0.19, 0.21], and 0 where the a between them is whole.
TEST(XmtoAudio, ThePhoBesideItGivesVisemesAtItsTimes) {
  const auto doc = load_xmto(fapc::test::corpus_dir() + kRecording);
  ASSERT_TRUE(doc.ok()) << format_diagnostic(doc.error());
  EXPECT_DOUBLE_EQ(test::value_at(doc->timeline, "viseme.PP", 1.055), 63);
  EXPECT_DOUBLE_EQ(test::value_at(doc->timeline, "viseme.PP", 1.20), 63);
  EXPECT_DOUBLE_EQ(test::value_at(doc->timeline, "viseme.PP", 1.13), 0);  // the a between them
  EXPECT_DOUBLE_EQ(test::value_at(doc->timeline, "viseme.PP", 0.9), 0);   // before the recording
  int pp = 0;
  for (const Clip& clip : doc->timeline.clips)
    if (clip.target == "viseme.PP") {
      ++pp;
      EXPECT_GE(clip.begin, 1.0);
      EXPECT_EQ(clip.source.line, 7);
    }
  EXPECT_EQ(pp, 2);
}

// A folder of its own per test: a WAV (and maybe a .pho) next to the document.
struct Folder {
  fs::path dir;
  explicit Folder(const std::string& name) : dir(fs::temp_directory_path() / ("fapc-xmto-audio-" + name)) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Folder() { fs::remove_all(dir); }
  void write(const std::string& name, const std::string& bytes) const {
    std::ofstream(dir / name, std::ios::binary) << bytes;
  }
  std::string doc(const std::string& body) const {
    write("t.xmt", test::document(body));
    return (dir / "t.xmt").string();
  }
};

// A mono 16-bit WAV of `count` samples at 1000 Hz, all `value`.
std::string wav(std::size_t count, std::int16_t value = 100) {
  AudioTrack track;
  track.sample_rate = 1000;
  track.samples.assign(count, value);
  return wav_bytes(track);
}

std::string error_of(const std::string& path, const XmtoOptions& options = {}) {
  const auto doc = load_xmto(path, options);
  return doc ? "no error" : format_diagnostic(doc.error());
}

TEST(XmtoAudio, DurAndClipEndCutTheRecordingAndWithoutPhoThereAreNoVisemes) {
  Folder folder("cut");
  folder.write("a.wav", wav(2000));
  const auto whole = load_xmto(folder.doc(R"(<audio src="a.wav" begin="0.5"/>)"));
  ASSERT_TRUE(whole.ok()) << format_diagnostic(whole.error());
  ASSERT_EQ(whole->timeline.audio.size(), 1u);
  EXPECT_EQ(whole->timeline.audio[0].samples.size(), 2000u);
  EXPECT_TRUE(whole->timeline.clips.empty());
  EXPECT_DOUBLE_EQ(whole->timeline.end(), 2.5);
  for (const char* cut : {R"(<audio src="a.wav" dur="0.5s"/>)", R"(<audio src="a.wav" clipEnd="500ms"/>)"}) {
    const auto doc = load_xmto(folder.doc(cut));
    ASSERT_TRUE(doc.ok()) << format_diagnostic(doc.error());
    ASSERT_EQ(doc->timeline.audio.size(), 1u) << cut;
    EXPECT_EQ(doc->timeline.audio[0].samples.size(), 500u) << cut;
    EXPECT_DOUBLE_EQ(doc->timeline.end(), 0.5) << cut;
  }
}

TEST(XmtoAudio, ErrorsAreAtTheElement) {
  Folder folder("errors");
  const std::string at = (folder.dir / "t.xmt").string() + ":3:";
  EXPECT_EQ(error_of(folder.doc(R"(<audio begin="1"/>)")), at + "1: error: audio needs src naming a WAV file");
  EXPECT_EQ(error_of(folder.doc(R"(<audio src="missing.wav"/>)")).rfind(at + "8: error: audio 'missing.wav': ", 0), 0u)
      << error_of(folder.doc(R"(<audio src="missing.wav"/>)"));
  std::string float_wav = wav(10);
  float_wav[20] = 3;  // format tag: IEEE float
  folder.write("float.wav", float_wav);
  const std::string refused = error_of(folder.doc(R"(<audio src="float.wav"/>)"));
  EXPECT_EQ(refused.rfind(at + "8: error: audio 'float.wav': the WAV file is 32-bit float", 0), 0u) << refused;
  const std::string outside = error_of(folder.doc(R"(<audio src="../elsewhere.wav"/>)"));
  EXPECT_EQ(outside.rfind(at + "8: error: ", 0), 0u) << outside;
  EXPECT_NE(outside.find("--allow-include"), std::string::npos) << outside;
  folder.write("a.wav", wav(100));
  XmtoOptions small;
  small.max_audio_bytes = 100;
  const std::string limited = error_of(folder.doc(R"(<audio src="a.wav"/>)"), small);
  EXPECT_EQ(limited.rfind(at + "8: error: ", 0), 0u) << limited;
  EXPECT_NE(limited.find("--max-decompressed-bytes"), std::string::npos) << limited;
  folder.write("a.pho", "m notanumber\n");
  const std::string bad_pho = error_of(folder.doc(R"(<audio src="a.wav"/>)"));
  EXPECT_EQ(bad_pho.rfind((folder.dir / "a.pho").string() + ":1:", 0), 0u) << bad_pho;
  fs::remove(folder.dir / "a.pho");
  EXPECT_EQ(error_of(folder.doc(R"(<audio src="a.wav" clipEnd="soon"/>)")),
            at + "20: error: clipEnd 'soon' is not a clock value");
}

}  // namespace
}  // namespace fapc::xmt

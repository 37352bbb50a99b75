// `fapc compile` of an XMT-Omega document with an `audio` element: the recording comes back out of
// -o x.wav, placed at the element's begin, and -o x.mp4 carries it beside the face.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

std::uint32_t u32_at(const std::string& b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}

struct TempDir {
  // One folder per test: ctest runs the tests of this file at the same time.
  fs::path path = fs::temp_directory_path() /
                  (std::string("fapc-xmto-audio-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

// mama.wav is a plain 44-byte-header mono 16-bit file (fapc wrote it); the document places it at
// 1 s, so the output is the same header layout, one second of silence, then the same samples.
TEST(XmtoAudioCommand, TheWavOutputIsTheRecordingAtItsBegin) {
  TempDir tmp;
  const std::string out = (tmp.path / "r.wav").string();
  const test::CommandRun run = test::run_fapc("compile corpus/xmto/recording.xmt -o '" + out + "'");
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const std::string in = test::read_text(test::corpus_dir() + "/xmto/recording/mama.wav");
  const std::string written = test::read_text(out);
  ASSERT_GT(in.size(), 44u);
  ASSERT_EQ(in.substr(36, 4), "data");  // the layout this test assumes
  const std::uint32_t rate = u32_at(in, 24);
  EXPECT_EQ(u32_at(written, 24), rate);
  ASSERT_EQ(written.size(), in.size() + 2 * rate);
  EXPECT_EQ(written.substr(44, 2 * rate), std::string(2 * rate, '\0'));
  EXPECT_TRUE(written.substr(44 + 2 * rate) == in.substr(44));
}

TEST(XmtoAudioCommand, TheMp4HasTheFaceAndTheSound) {
  TempDir tmp;
  const std::string out = (tmp.path / "r.mp4").string();
  const test::CommandRun run = test::run_fapc("compile corpus/xmto/recording.xmt -o '" + out + "'");
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const test::CommandRun info = test::run_fapc("info '" + out + "'");
  ASSERT_EQ(info.exit_status, 0) << info.err;
  EXPECT_NE(info.out.find("FBA stream"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("audio sample rate: 22050"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("audio start: 1.000"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("viseme"), std::string::npos) << info.out;  // the .pho's visemes
}

TEST(XmtoAudioCommand, ABadRecordingIsAnErrorAndNoFile) {
  TempDir tmp;
  const fs::path doc = tmp.path / "t.xmt";
  test::run_shell("printf '<XMT-O>\\n<body>\\n<audio src=\"gone.wav\"/>\\n</body></XMT-O>\\n' > '" + doc.string() +
                  "'");
  const std::string out = (tmp.path / "r.wav").string();
  const test::CommandRun run = test::run_fapc("compile '" + doc.string() + "' -o '" + out + "'");
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_EQ(run.err.rfind(doc.string() + ":3:8: error: audio 'gone.wav': ", 0), 0u) << run.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace fapc

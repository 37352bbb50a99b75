// Every real .fap file of the corpus is read, written in the safe form and read back unchanged.
#include <gtest/gtest.h>

#include "fapc/codec/fap_file.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

std::vector<std::string> corpus_files() { return test::files_under(test::corpus_dir() + "/fap", ".fap"); }

TEST(FapCorpus, EveryFileIsRead) {
  const auto files = corpus_files();
  // 196 files from five projects (docs/fap-files.md section 7); a silently skipped file fails.
  ASSERT_EQ(files.size(), 196u);
  std::size_t frames = 0;
  for (const std::string& path : files) {
    auto read = read_fap_text(test::read_text(path), path);
    ASSERT_TRUE(read.ok()) << format_diagnostic(read.error());
    frames += read->sequence.frames.size();
  }
  EXPECT_EQ(frames, 2277u);  // the frame total the survey counted
}

TEST(FapCorpus, WriteThenReadGivesIdenticalValues) {
  for (const std::string& path : corpus_files()) {
    auto first = read_fap_text(test::read_text(path), path);
    ASSERT_TRUE(first.ok());
    const std::string written = write_fap_text(first->sequence);
    auto second = read_fap_text(written, "written");
    ASSERT_TRUE(second.ok()) << path << ": " << format_diagnostic(second.error());
    EXPECT_TRUE(second->warnings.empty()) << path << ": the safe form must read without warnings";
    const auto& a = first->sequence.frames;
    const auto& b = second->sequence.frames;
    ASSERT_EQ(a.size(), b.size()) << path;
    EXPECT_EQ(first->sequence.fps, second->sequence.fps) << path;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_TRUE(a[i].same_content(b[i])) << path << " frame " << i;
      EXPECT_EQ(a[i].number, b[i].number) << path << " frame " << i;
    }
  }
}

TEST(FapCorpus, CrlfTwinsReadTheSameAsTheirLfOriginals) {
  const char* emotions[] = {"anger", "beg", "disgust", "fear", "happy-for", "hate", "joy", "pride"};
  for (const char* name : emotions) {
    const std::string lf = test::corpus_dir() + "/fap/copperdong__Xface/" + name + ".fap";
    const std::string crlf = test::corpus_dir() + "/fap/bestdpf__xface-new/" + name + ".fap";
    auto a = read_fap_text(test::read_text(lf), lf);
    auto b = read_fap_text(test::read_text(crlf), crlf);
    ASSERT_TRUE(a.ok() && b.ok()) << name;
    EXPECT_FALSE(a->facts.crlf);
    EXPECT_TRUE(b->facts.crlf) << name;
    EXPECT_EQ(write_fap_text(a->sequence), write_fap_text(b->sequence)) << name;
  }
}

// A sample of normalised outputs, reviewed by hand when first written: the header name is the
// base name, masks have 68 tokens, values are the input's, frames are numbered from 0.
TEST(FapCorpus, GoldenNormalisedOutputs) {
  const char* samples[] = {
      "copperdong__Xface/test.fap",
      "philippedax__vreng/S136_surp.fap",
      "SEMAINE__SEMAINE-3.1/example2.v1513aba.fap",
      "isir__greta/UniqueId_214.fap",
      "isir__greta/AU Interpolation_2.fap",
  };
  for (const char* sample : samples) {
    const std::string path = test::corpus_dir() + "/fap/" + sample;
    auto read = read_fap_text(test::read_text(path), path);
    ASSERT_TRUE(read.ok()) << sample;
    std::string golden = std::string("golden/fap/") + sample;
    test::expect_golden(golden, write_fap_text(read->sequence));
  }
}

}  // namespace
}  // namespace fapc

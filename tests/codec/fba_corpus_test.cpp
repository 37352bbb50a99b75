// Every real .fap file of the corpus encodes, decodes and verifies (round trip within half a
// step, re-encoding identical), at fap_quant 1 and 2.
#include <gtest/gtest.h>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

TEST(FbaCorpus, EveryFapFileRoundTrips) {
  const auto files = test::files_under(test::corpus_dir() + "/fap", ".fap");
  ASSERT_EQ(files.size(), 196u);  // as counted in tests/fapfile: none may be skipped silently
  std::size_t frames = 0;
  for (const std::string& path : files) {
    auto read = read_fap_text(test::read_text(path), path);
    ASSERT_TRUE(read.ok()) << path;
    for (const int quant : {1, 2}) {
      FbaEncodeOptions options;
      options.quant = quant;
      auto encoded = encode_fba(read->sequence, options);
      ASSERT_TRUE(encoded.ok()) << path << ": " << format_diagnostic(encoded.error());
      const Status verified = verify_fba(read->sequence, *encoded, options, path);
      EXPECT_TRUE(verified.ok()) << (verified.ok() ? "" : format_diagnostic(verified.error()));
    }
    frames += read->sequence.frames.size();
  }
  EXPECT_EQ(frames, 2277u);
}

// At fap_quant 0 (lossless) values beyond +-1860 cannot be coded: the same 4 Xface files (and
// their CRLF twins) as with the reference codec (fba-bitstream.md 12.4) are refused, with the
// FAP and frame named; every other file is coded exactly.
TEST(FbaCorpus, LosslessCodingRefusesOnlyTheFilesTheReferenceCannotCode) {
  std::vector<std::string> refused;
  for (const std::string& path : test::files_under(test::corpus_dir() + "/fap", ".fap")) {
    auto read = read_fap_text(test::read_text(path), path);
    ASSERT_TRUE(read.ok());
    FbaEncodeOptions options;
    options.quant = 0;
    auto encoded = encode_fba(read->sequence, options);
    if (!encoded.ok()) {
      EXPECT_NE(encoded.error().message.find("beyond the largest range"), std::string::npos);
      refused.push_back(path.substr(path.rfind('/') + 1));
      continue;
    }
    EXPECT_TRUE(verify_fba(read->sequence, *encoded, options).ok()) << path;
  }
  std::sort(refused.begin(), refused.end());
  EXPECT_EQ(refused, (std::vector<std::string>{"beg.fap", "beg.fap", "disgust.fap", "disgust.fap", "hate.fap",
                                                "hate.fap", "pride.fap", "pride.fap"}));
}

}  // namespace
}  // namespace fapc

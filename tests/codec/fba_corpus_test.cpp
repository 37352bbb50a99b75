// Every real .fap file of the corpus encodes, decodes and verifies (round trip within half a
// step, re-encoding identical), at fap_quant 1 with fitted masks and at 2 with the input's masks kept.
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
      options.masks = quant == 1 ? FbaMaskMode::fit : FbaMaskMode::keep;
      auto encoded = encode_fba(read->sequence, options);
      ASSERT_TRUE(encoded.ok()) << path << ": " << format_diagnostic(encoded.error());
      const Status verified = verify_fba(read->sequence, *encoded, options, path);
      EXPECT_TRUE(verified.ok()) << (verified.ok() ? "" : format_diagnostic(verified.error()));
    }
    frames += read->sequence.frames.size();
  }
  EXPECT_EQ(frames, 2277u);
}

// At fap_quant 0 (lossless) values beyond +-1860 cannot be coded. With the input's masks kept, the
// same 4 Xface files (and their CRLF twins) as with the reference codec (docs/fba-bitstream.md
// section 12.4) are refused, with the FAP and frame named: their mask changes put an intra plane
// where a value is beyond the range. With fitted masks the eyelids that cause those changes stay in
// the mask, no intra plane is needed there, and every file is coded exactly.
std::vector<std::string> refused_at_quant_zero(FbaMaskMode masks) {
  std::vector<std::string> refused;
  for (const std::string& path : test::files_under(test::corpus_dir() + "/fap", ".fap")) {
    auto read = read_fap_text(test::read_text(path), path);
    EXPECT_TRUE(read.ok());
    FbaEncodeOptions options;
    options.quant = 0;
    options.masks = masks;
    auto encoded = encode_fba(read->sequence, options);
    if (!encoded.ok()) {
      EXPECT_NE(encoded.error().message.find("beyond the largest range"), std::string::npos);
      refused.push_back(path.substr(path.rfind('/') + 1));
      continue;
    }
    EXPECT_TRUE(verify_fba(read->sequence, *encoded, options).ok()) << path;
  }
  std::sort(refused.begin(), refused.end());
  return refused;
}

TEST(FbaCorpus, LosslessCodingRefusesOnlyTheFilesTheReferenceCannotCode) {
  EXPECT_EQ(refused_at_quant_zero(FbaMaskMode::keep),
            (std::vector<std::string>{"beg.fap", "beg.fap", "disgust.fap", "disgust.fap", "hate.fap", "hate.fap",
                                      "pride.fap", "pride.fap"}));
  EXPECT_EQ(refused_at_quant_zero(FbaMaskMode::fit), std::vector<std::string>{});
}

}  // namespace
}  // namespace fapc

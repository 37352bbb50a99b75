// A script going to .fba and .fap is rendered frame by frame, never held as frames
// (docs/architecture.md, "Streaming"); the usual load and writers, a second and independent way,
// say what it must give: the same bytes, warnings and errors, over every script of the corpus
// (good and bad) at several frame rates, flavours and limits.
#include <gtest/gtest.h>

#include <filesystem>

#include "fapc/pipeline/convert.hpp"
#include "pipeline_test_helpers.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;
using pipeline::ConvertOptions;

// The usual way: the whole load (frames and all), then each writer's bytes up to the first error.
using test::load_then_write;
using test::LoadedWay;

std::vector<ConvertOptions> settings() {
  std::vector<ConvertOptions> all(6);
  // The speech engine does not say a text twice the same way in one process (a talk's visemes
  // differ by one unit the second time): the letter table does, and the streaming is not about it.
  for (ConvertOptions& options : all) options.speech_engine = false;
  all[1].fps = 10;
  all[2].fps = 30;
  all[2].quant = 7;
  all[2].masks = "keep";
  all[2].fap_flavour = FapFlavour::greta_java;
  all[3].fps = 100;
  all[3].fap_flavour = FapFlavour::semaine;
  all[4].limits.max_frames = 40;  // most corpus scripts are longer
  all[5].strict = true;
  return all;
}

TEST(StreamedRender, GivesTheBytesWarningsAndErrorsOfLoadingAndWriting) {
  const test::TempFolder tmp;
  std::size_t scripts = 0, failing = 0, warned = 0;
  for (const std::string& input : test::corpus_scripts()) {
    ++scripts;
    for (const ConvertOptions& options : settings()) {
      const std::vector<pipeline::OutputRequest> outputs = {{tmp / "x.fap", ""}, {tmp / "x.fba", ""}};
      const LoadedWay expected = load_then_write(input, outputs, options);
      fs::remove(tmp / "x.fap");
      fs::remove(tmp / "x.fba");
      const pipeline::ConvertResult streamed = pipeline::convert(input, outputs, options);
      SCOPED_TRACE(input + " at " + std::to_string(options.fps) + " fps");
      EXPECT_TRUE(streamed.loaded.frames.frames.empty());  // streamed, not loaded
      failing += expected.error.has_value();
      warned += !expected.warnings.empty();
      test::expect_as_loaded(streamed, expected, outputs);
      if (!expected.error) {
        EXPECT_EQ(streamed.frames.count, expected.frames);
      }
    }
  }
  EXPECT_GT(scripts, 40u / test::kSweepStride);
  EXPECT_GT(failing, 10u / test::kSweepStride);  // the bad corpus and the low limit: errors compared, not only bytes
  EXPECT_GT(warned, 0u);
  for (const auto& entry : fs::directory_iterator(tmp.path()))  // no temporary file left behind
    EXPECT_FALSE(entry.path().filename().string().starts_with(".fapc-tmp-")) << entry.path();
}

}  // namespace
}  // namespace fapc

// Convert and verify from C++, as a program using the library would: a corpus file to each
// output kind, read back, checked.
#include <gtest/gtest.h>

#include <filesystem>

#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/info.hpp"
#include "fapc/pipeline/verify.hpp"
#include "pipeline_test_helpers.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;
using pipeline::ConvertOptions;

std::string anger() { return test::corpus_dir() + "/examples/fap/anger.fap"; }

TEST(Convert, OneLoadWritesEveryOutputAndEachReadsBack) {
  const test::TempFolder tmp;
  const std::vector<pipeline::OutputRequest> outputs = {{tmp / "a.fba", ""}, {tmp / "a.mp4", ""}, {tmp / "a.json", ""}};
  const pipeline::ConvertResult result = pipeline::convert(anger(), outputs, ConvertOptions{});
  ASSERT_TRUE(result.ok()) << format_diagnostic(*result.error);
  EXPECT_EQ(result.written, (std::vector<std::string>{tmp / "a.fba", tmp / "a.mp4", tmp / "a.json"}));
  EXPECT_EQ(result.loaded.frames.frames.size(), 108u);  // as `fapc info` and the main-job test show
  for (const char* back : {"a.fba", "a.mp4"}) {
    auto loaded = pipeline::load(tmp / back, ConvertOptions{});
    ASSERT_TRUE(loaded) << format_diagnostic(loaded.error());
    EXPECT_EQ(loaded->frames.frames.size(), 108u) << back;
    const pipeline::VerifyResult verified = pipeline::verify(tmp / back, ConvertOptions{});
    EXPECT_TRUE(verified.ok()) << back << ": " << format_diagnostic(*verified.error);
    EXPECT_NE(verified.summary.find("108 frames"), std::string::npos) << verified.summary;
  }
}

TEST(Convert, StandardOutputBytesAreReturnedNotWritten) {
  const pipeline::ConvertResult result = pipeline::convert(anger(), {{"-", "fap"}}, ConvertOptions{});
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result.written.empty());
  EXPECT_EQ(result.standard_output.rfind("2.1 ", 0), 0u) << result.standard_output.substr(0, 40);
}

TEST(Convert, StrictTurnsWarningsIntoAnErrorAndWritesNothing) {
  const test::TempFolder tmp;
  ConvertOptions options;
  options.strict = true;
  // greta-lips.fap gives one warning (the main-job test's summary line).
  const auto result =
      pipeline::convert(test::corpus_dir() + "/examples/fap/greta-lips.fap", {{tmp / "g.fap", ""}}, options);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error->kind, ErrorKind::bad_input);
  EXPECT_EQ(result.warnings.size(), 1u);
  EXPECT_FALSE(fs::exists(tmp / "g.fap"));
}

TEST(Info, FactsComeFromTheOneRead) {
  auto info = pipeline::describe(anger());
  ASSERT_TRUE(info) << format_diagnostic(info.error());
  EXPECT_EQ((*info)["kind"], "fap");
  EXPECT_EQ((*info)["frames"], 108);
  ASSERT_TRUE(info->contains("format"));
  EXPECT_TRUE((*info)["format"].contains("variant"));
}

TEST(Loading, AScriptCanStopAtItsTimeline) {
  ConvertOptions options;
  options.render = false;
  auto loaded = pipeline::load(test::corpus_dir() + "/examples/mimic/figure3.mimic", options);
  ASSERT_TRUE(loaded) << format_diagnostic(loaded.error());
  ASSERT_TRUE(loaded->timeline);
  EXPECT_FALSE(loaded->timeline->clips.empty());
  EXPECT_TRUE(loaded->frames.frames.empty());
  EXPECT_FALSE(loaded->curves);
}

}  // namespace
}  // namespace fapc

// Every SmartBody-style BML file of corpus/ (SmartBody's scenario files and Greta's NVBG
// ExampleScenario, catalog.tsv) compiles to .fap: recorded speech with its marks' times, lips
// rows, FaceFX curves kept for their timing (docs/bml.md, "The corpus"). Their WAV files are not
// in the corpus: each compiles without its voice, with the warning that says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "fapc/pipeline/convert.hpp"
#include "support/param_names.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> corpus_files() {
  std::vector<std::string> out;
  for (const char* folder : {"bml/worldforge__smartbody", "bml/isir__greta/ExampleScenario"})
    for (const std::string& path : test::files_under(test::corpus_dir() + "/" + folder, ".bml"))
      out.push_back(fs::relative(path, test::corpus_dir()).string());
  return out;
}

TEST(BmlSmartBodyCorpus, AllThirtyFiveFiles) { EXPECT_EQ(corpus_files().size(), 35U); }

class BmlSmartBodyFile : public testing::TestWithParam<std::string> {};

TEST_P(BmlSmartBodyFile, CompilesWithItsRecordedTiming) {
  const std::string relative = GetParam();
  pipeline::ConvertOptions options;
  options.speech_engine = false;  // recorded speech needs none: were it asked, this would show
  const std::string output = (fs::temp_directory_path() / ("fapc-" + test::identifier(relative) + ".fap")).string();
  fs::remove(output);
  const pipeline::ConvertResult result =
      pipeline::convert(test::corpus_dir() + "/" + relative, {{output, ""}}, options);
  ASSERT_TRUE(result.ok()) << result.error->message;
  EXPECT_TRUE(fs::is_regular_file(output));
  EXPECT_GT(result.frames.count, 0);
  bool missing = false;
  bool no_engine = false;
  for (const Diagnostic& w : result.warnings) {
    missing = missing || w.code == "bml.recorded_audio_missing";
    no_engine = no_engine || w.code == "bml.no_speech_engine";
    EXPECT_NE(w.code, "bml.unknown_viseme") << w.message;
  }
  EXPECT_TRUE(missing);
  EXPECT_FALSE(no_engine) << "recorded speech went to synthesis";
  fs::remove(output);
}

INSTANTIATE_TEST_SUITE_P(Files, BmlSmartBodyFile, testing::ValuesIn(corpus_files()), test::file_param_name);

}  // namespace
}  // namespace fapc

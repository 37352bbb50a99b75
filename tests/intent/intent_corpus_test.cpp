// Every FML-APML and APML file of corpus/ (Greta's and SEMAINE's, MaryTTS's examples; catalog.tsv)
// compiles to .fap, or is refused with a positioned error naming a real defect of that file. The
// refusals are listed here with the defect; any other refusal, or a listed file that compiles,
// fails the test. Each file is read by its root element (--from xml), as the .example files are not
// named .xml.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "fapc/pipeline/convert.hpp"
#include "intent_test_support.hpp"
#include "support/param_names.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

// File (under corpus/) -> what its error must say, and the defect.
const std::map<std::string, std::string>& refused() {
  static const std::map<std::string, std::string> files = {
      // p1 starts at s1:tm0, but the speech's first mark is tm1: the reference names nothing.
      {"fml-apml/isir__greta/DemoEN/2-SeeYou speech delayed.xml", "no mark 'tm0' in a speech 's1'"},
  };
  return files;
}

// Files that animate nothing: Greta's stop and overlap commands (composition="replace"), an empty
// speech and no intention. They compile to a .fap of no frames.
bool empty_document(const std::string& relative) {
  return relative == "fml-apml/isir__greta/DemoEN/stop.xml" || relative == "fml-apml/isir__greta/DemoEN/Overlap.xml";
}

std::vector<std::string> corpus_files() {
  std::vector<std::string> out;
  for (const char* folder : {"fml-apml", "apml"})
    for (const auto& entry : fs::recursive_directory_iterator(test::corpus_dir() + "/" + folder))
      if (entry.is_regular_file()) out.push_back(fs::relative(entry.path(), test::corpus_dir()).string());
  std::sort(out.begin(), out.end());
#ifdef FAPC_SANITIZED_BUILD
  // The sanitizers run 10-20 times slower: every fourth file.
  std::vector<std::string> sample;
  for (std::size_t i = 0; i < out.size(); i += 4) sample.push_back(out[i]);
  return sample;
#else
  return out;
#endif
}

class IntentCorpus : public testing::TestWithParam<std::string> {};

TEST_P(IntentCorpus, CompilesOrIsRefusedForARealDefect) {
  const std::string relative = GetParam();
  pipeline::ConvertOptions options;
  options.input_kind = "xml";
  const std::string output = test::write_temp("corpus.fap", "");
  fs::remove(output);
  const pipeline::ConvertResult result =
      pipeline::convert(test::corpus_dir() + "/" + relative, {{output, ""}}, options);
  const auto expected = refused().find(relative);
  if (expected == refused().end()) {
    ASSERT_TRUE(result.ok()) << result.error->message;
    EXPECT_TRUE(fs::is_regular_file(output));
    EXPECT_EQ(result.frames.count == 0, empty_document(relative)) << result.frames.count << " frames";
    fs::remove(output);
    return;
  }
  ASSERT_FALSE(result.ok()) << relative << " compiles, but is listed as refused";
  EXPECT_GT(result.error->where.line, 0);
  EXPECT_GT(result.error->where.column, 0);
  EXPECT_NE(result.error->where.file.str().find(relative), std::string::npos);
  EXPECT_NE(result.error->message.find(expected->second), std::string::npos) << result.error->message;
  EXPECT_FALSE(fs::exists(output)) << "no partial output";
}

INSTANTIATE_TEST_SUITE_P(Files, IntentCorpus, testing::ValuesIn(corpus_files()), test::file_param_name);

}  // namespace
}  // namespace fapc

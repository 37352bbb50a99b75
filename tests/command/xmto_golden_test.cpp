// Every document of corpus/xmto/ compiled by the fapc program to curves JSON, .fap and the
// timeline dump, compared with corpus/golden/xmto/. Goes through the registry, so `animation src`
// reaches every registered front end. The composition of a Mimic program, an FML document and a
// .fap file (compose.xmt) runs only once the Mimic and FML inputs are registered.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

bool input_kind_registered(const std::string& sample) {
  const test::CommandRun run = test::run_fapc("info " + sample);
  return run.err.find("unknown input kind") == std::string::npos;
}

void expect_outputs_match_goldens(const std::string& path) {
  const std::string stem = fs::path(path).stem().string();
  for (const char* kind : {"json", "fap", "timeline"}) {
    const test::CommandRun run = test::run_fapc("compile " + path + " -o - --to " + kind);
    ASSERT_EQ(run.exit_status, 0) << path << " to " << kind << ": " << run.err;
    test::expect_golden("golden/xmto/" + stem + "." + kind, run.out);
  }
}

TEST(XmtoGolden, EveryDocumentCompilesToItsGoldens) {
  int compiled = 0;
  for (const std::string& full : test::files_under(test::corpus_dir() + "/xmto", ".xmt")) {
    const std::string path = fs::relative(full, test::source_dir()).string();
    if (fs::path(path).filename() == "compose.xmt") continue;
    expect_outputs_match_goldens(path);
    ++compiled;
  }
  EXPECT_GE(compiled, 5);
}

TEST(XmtoGolden, ComposesMimicFmlAndFapInOnePar) {
  if (!input_kind_registered("corpus/xmto/parts/hello.mimic") ||
      !input_kind_registered("corpus/xmto/parts/smile.fml")) {
    GTEST_SKIP() << "the Mimic or FML input is not registered in this build";
  }
  expect_outputs_match_goldens("corpus/xmto/compose.xmt");
}

}  // namespace
}  // namespace fapc

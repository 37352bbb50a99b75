// The bundled examples compiled by the real program, compared with reviewed golden files
// (regenerate with FAPC_REGENERATE_GOLDEN=1, review with `git diff corpus/`).
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_support.hpp"

namespace fapc {
namespace {

void expect_output_golden(const std::string& input, const std::string& kind, const std::string& golden,
                          const std::string& options = "") {
  const test::CommandRun run = test::run_fapc("compile " + input + " -o - --to " + kind + options);
  ASSERT_EQ(run.exit_status, 0) << input << ": " << run.err;
  test::expect_golden(golden, run.out);
}

TEST(GoldenOutputs, MimicExamples) {
  for (const std::string name : {"table2", "figure3"}) {
    const std::string input = "corpus/mimic/" + name + ".mimic";
    expect_output_golden(input, "json", "mimic/golden/" + name + ".json");
    expect_output_golden(input, "fap", "mimic/golden/" + name + ".fap");
  }
}

TEST(GoldenOutputs, FmlExamples) {
  // FML Figure 7 waits for its event: the golden is the "Bye" branch.
  const std::vector<std::pair<std::string, std::string>> examples = {
      {"figure5", ""}, {"figure6", ""},      {"figure7", " --event user=1"},
      {"figure8", ""}, {"hindawi-alg1", ""}, {"tour", ""}};
  EXPECT_EQ(test::files_under(test::corpus_dir() + "/fml", ".fml").size(), examples.size());
  for (const auto& [name, options] : examples) {
    const std::string input = "corpus/fml/" + name + ".fml";
    expect_output_golden(input, "json", "golden/fml/" + name + ".json", options);
    expect_output_golden(input, "fap", "golden/fml/" + name + ".fap", options);
  }
}

TEST(GoldenOutputs, AlgebraExamples) {
  const std::vector<std::string> inputs = test::files_under(test::corpus_dir() + "/algebra", ".combine");
  ASSERT_EQ(inputs.size(), 5u);
  for (const std::string& input : inputs) {
    const std::string stem = std::filesystem::path(input).stem().string();
    // The examples take their operands from corpus/fap/, beside their own folder.
    expect_output_golden(input, "fap", "algebra/golden/" + stem + ".fap", " --allow-include corpus");
  }
}

// `fapc plot` SVGs (docs/cli.md "Plot"): per-clip panels, an overlay of a group with its legend
// and a zero parameter left out, a single-frame input drawn as points.
TEST(GoldenOutputs, Plots) {
  const std::string dir = test::binary_dir() + "/golden-plots";
  std::filesystem::create_directories(dir);
  const std::vector<std::pair<std::string, std::string>> plots = {
      {"table2-per-clip", "corpus/mimic/table2.mimic --per-clip"},
      {"figure3-lips-overlay", "corpus/examples/mimic/figure3.mimic --faps lips,jaw --overlay"},
      {"greta-lips-points", "corpus/examples/fap/greta-lips.fap --faps 3-8"},
      {"joy-panels", "corpus/examples/fap/joy.fap --faps brows,head"}};
  for (const auto& [name, args] : plots) {
    const std::string out = dir + "/" + name + ".svg";
    const test::CommandRun run = test::run_fapc("plot " + args + " -o '" + out + "'");
    ASSERT_EQ(run.exit_status, 0) << args << ": " << run.err;
    test::expect_golden("golden/plot/" + name + ".svg", test::read_text(out));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fapc

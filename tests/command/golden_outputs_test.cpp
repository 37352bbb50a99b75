// The bundled examples compiled by the real program, compared with reviewed golden files
// (regenerate with FAPC_REGENERATE_GOLDEN=1, review with `git diff corpus/`).
#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace fapc {
namespace {

void expect_output_golden(const std::string& input, const std::string& kind, const std::string& golden) {
  const test::CommandRun run = test::run_fapc("compile " + input + " -o - --to " + kind);
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

}  // namespace
}  // namespace fapc

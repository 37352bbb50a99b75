// Pipes (docs/cli.md, "Pipes"): a reader that goes away early makes fapc fail with a message and
// exit status 1, and standard input's temporary copy is removed in every case. TMPDIR points the
// copy into a folder of the test's own, which must be empty afterwards.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

struct PipeRun {
  int fapc_status;
  std::string err;
  bool temporary_left;
};

// Runs fapc (from the source folder, TMPDIR a fresh folder) with standard input from `input` and
// its standard output into `reader`; the status is fapc's, not the reader's.
PipeRun run_piped(const std::string& args, const std::string& input, const std::string& reader) {
  const fs::path tmp = fs::path(test::binary_dir()) / "pipes-test-tmp";
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  const std::string err = (tmp / "err").string(), status = (tmp / "status").string();
  const fs::path copies = tmp / "copies";
  fs::create_directories(copies);
  test::run_shell("cd '" + test::source_dir() + "' && { TMPDIR='" + copies.string() + "' '" + test::fapc_program() +
                  "' " + args + " < '" + input + "' 2>'" + err + "'; echo $? > '" + status + "'; } | " + reader +
                  " > /dev/null");
  PipeRun run{std::stoi(test::read_text(status)), test::read_text(err), !fs::is_empty(copies)};
  fs::remove_all(tmp);
  return run;
}

TEST(Pipes, ClosedReaderIsAnIoErrorNotADeath) {
  // 1000 frames of .fap text (176 kB) are far more than a pipe holds (64 kB), so fapc is still
  // writing when head has gone.
  const PipeRun run = run_piped("compile - --from fap -o - --to fap", "corpus/mimic/golden/figure3.fap", "head -c 1");
  EXPECT_EQ(run.fapc_status, 1) << run.err;
  EXPECT_EQ(run.err, "<standard output>: error: cannot write: Broken pipe (the reading end of the pipe closed)\n");
  EXPECT_FALSE(run.temporary_left);
}

TEST(Pipes, StandardInputCopyIsRemovedAfterSuccessAndFailure) {
  const PipeRun ok =
      run_piped("compile - --from mimic -o - --to json", "corpus/cli/include-from-working-folder.mimic", "cat");
  EXPECT_EQ(ok.fapc_status, 0) << ok.err;
  EXPECT_FALSE(ok.temporary_left);
  const PipeRun bad = run_piped("compile - --from fba -o - --to json", "corpus/cli/README.md", "cat");
  EXPECT_EQ(bad.fapc_status, 1) << bad.err;
  EXPECT_EQ(bad.err.rfind("-: ", 0), 0u) << "diagnostics name standard input '-': " << bad.err;
  EXPECT_FALSE(bad.temporary_left);
}

}  // namespace
}  // namespace fapc

// Helpers shared by every test program: where the sources and the corpus are, and golden files.
#pragma once

#include <string>
#include <vector>

namespace fapc::test {

std::string source_dir();    // the project's top folder
std::string binary_dir();    // the build folder
std::string corpus_dir();    // source_dir() + "/corpus"
std::string fapc_program();  // the built fapc program

std::string read_text(const std::string& path);  // bytes as they are; fails the test if missing
// A folder of this test process's own for the files a test writes: "fapc-<name>-<pid>" under the
// system's temporary folder, made if it is not there.
std::string scratch_folder(const std::string& name);
// Every regular file under `folder` whose name ends with `suffix`, sorted.
std::vector<std::string> files_under(const std::string& folder, const std::string& suffix);

// Compares `actual` with the golden file at `path` (relative to corpus/). With the environment
// variable FAPC_REGENERATE_GOLDEN=1 the golden file is rewritten instead, and the test passes;
// review the result with `git diff corpus/` before committing (docs/testing.md).
void expect_golden(const std::string& path, const std::string& actual);

// Compares the part of the document at `path` (from the source folder) between the lines `begin`
// and `end` with `made`, the text generated from `source` (named in the failure); with
// FAPC_REGENERATE_GOLDEN=1 that part is rewritten instead.
void expect_generated_region(const std::string& path, const std::string& begin, const std::string& end,
                             const std::string& made, const std::string& source);

struct CommandRun {
  int exit_status = -1;
  std::string out;
  std::string err;
};
// Runs a shell command line and captures its exit status and output.
CommandRun run_shell(const std::string& command);
// Runs the built fapc with `args` (a shell-quoted string) from the source folder.
CommandRun run_fapc(const std::string& args);

}  // namespace fapc::test

// What is made from the one declaration of the command line (tools/fapc/cli_spec.cpp): the option
// tables of docs/cli.md match it (FAPC_REGENERATE_GOLDEN=1 rewrites them), every subcommand has a
// --help, the man page is well-formed roff and the completion scripts parse.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "support/test_support.hpp"

namespace fapc {
namespace {

constexpr const char* kBegin = "<!-- fapc help --markdown: begin -->\n";
constexpr const char* kEnd = "<!-- fapc help --markdown: end -->\n";

TEST(CliDeclaration, DocsTablesAreTheDeclaration) {
  const test::CommandRun run = test::run_fapc("help --markdown");
  ASSERT_EQ(run.exit_status, 0) << run.err;
  test::expect_generated_region("docs/cli.md", kBegin, kEnd, run.out, "the declaration in tools/fapc/cli_spec.cpp");
}

// The subcommands `fapc help --markdown` lists (the first column of its first table).
std::vector<std::string> subcommands() {
  std::vector<std::string> names;
  std::istringstream table(test::run_fapc("help --markdown").out);
  for (std::string line; std::getline(table, line) && !line.empty();)
    if (line.rfind("| `", 0) == 0) names.push_back(line.substr(3, line.find('`', 3) - 3));
  return names;
}

TEST(CliDeclaration, EverySubcommandHasHelp) {
  const std::vector<std::string> names = subcommands();
  ASSERT_GE(names.size(), 13u);
  for (const std::string& name : names) {
    for (const char* form : {" --help", " -h"}) {
      const test::CommandRun run = test::run_fapc(name + form);
      EXPECT_EQ(run.exit_status, 0) << name << form << ": " << run.err;
      EXPECT_EQ(run.out.rfind("usage: fapc " + name, 0), 0u) << name << form << ": " << run.out;
    }
    const test::CommandRun help = test::run_fapc("help " + name);
    EXPECT_EQ(help.out, test::run_fapc(name + " --help").out) << name;
  }
}

TEST(CliDeclaration, ManPageIsCleanRoff) {
  const test::CommandRun run = test::run_shell("'" + test::fapc_program() + "' help --man | groff -man -ww -z 2>&1");
  EXPECT_EQ(run.exit_status, 0);
  EXPECT_EQ(run.out, "") << "groff warnings on the man page";
  EXPECT_NE(test::run_fapc("help --man").out.find(".SH OPTIONS"), std::string::npos);
}

TEST(CliDeclaration, CompletionScriptsParse) {
  const test::CommandRun bash = test::run_shell(
      "'" + test::fapc_program() +
      "' help --bash-completion > completion.bash && "
      "bash -c 'source ./completion.bash && COMP_WORDS=(fapc comp) COMP_CWORD=1 && _fapc && echo ${COMPREPLY[@]} && "
      "COMP_WORDS=(fapc compile --ran) COMP_CWORD=2 && _fapc && echo ${COMPREPLY[@]} && "
      "COMP_WORDS=(fapc compile --ranges \"\") COMP_CWORD=3 && _fapc && echo ${COMPREPLY[@]} && "
      "COMP_WORDS=(fapc batch --to m) COMP_CWORD=3 && _fapc && echo ${COMPREPLY[@]}'; rm -f completion.bash");
  EXPECT_EQ(bash.exit_status, 0) << bash.err;
  EXPECT_EQ(bash.out, "compile\n--ranges\nfit max\nmp4\n");
  if (test::run_shell("command -v zsh").exit_status == 0) {
    const test::CommandRun zsh = test::run_shell("'" + test::fapc_program() +
                                                 "' help --zsh-completion > _fapc.zsh && zsh -n _fapc.zsh; "
                                                 "status=$?; rm -f _fapc.zsh; exit $status");
    EXPECT_EQ(zsh.exit_status, 0) << zsh.err;
  }
}

}  // namespace
}  // namespace fapc

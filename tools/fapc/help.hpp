// Everything made from the declaration of cli_spec.hpp for people and shells: the overview of
// `fapc`/`fapc help`, each subcommand's `--help`, the man page, the bash and zsh completions and
// the Markdown tables of docs/cli.md.
#pragma once

#include <ostream>
#include <string>

#include "fapc/cli_spec.hpp"

namespace fapc::cli {

// "fapc 0.1.0 (git 0123abcd4567)": the version of CMake's project() and, when built from a
// checkout, its revision.
std::string version_text();

void print_overview(std::ostream& out);
void print_command_help(const CommandSpec& command, std::ostream& out);

std::string man_page();         // roff, for share/man/man1/fapc.1
std::string bash_completion();  // for share/bash-completion/completions/fapc
std::string zsh_completion();   // for share/zsh/vendor-completions/_fapc
std::string markdown_tables();  // what docs/cli.md holds between its "options" markers

}  // namespace fapc::cli

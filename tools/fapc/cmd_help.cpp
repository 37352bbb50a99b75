// fapc help [COMMAND] | --man | --bash-completion | --zsh-completion | --markdown: the overview,
// one subcommand's help, or what packagers install, all from cli_spec.cpp.
#include <iostream>

#include "fapc/args.hpp"
#include "fapc/codec/did_you_mean.hpp"
#include "fapc/commands.hpp"
#include "fapc/help.hpp"

namespace fapc::cli {

namespace {

int run_help(const std::vector<std::string>& argv) {
  Args args("help", argv);
  if (!args.ok()) return usage_error("help", args);
  if (args.flag("man")) return std::cout << man_page(), kExitOk;
  if (args.flag("bash-completion")) return std::cout << bash_completion(), kExitOk;
  if (args.flag("zsh-completion")) return std::cout << zsh_completion(), kExitOk;
  if (args.flag("markdown")) return std::cout << markdown_tables(), kExitOk;
  if (args.positionals().empty()) {
    print_overview(std::cout);
    return kExitOk;
  }
  if (args.positionals().size() > 1) return usage_error("help", codes::cli::operands, "expected at most one COMMAND");
  const std::string& name = args.positionals().front();
  const CommandSpec* command = find_command_spec(name);
  if (!command) {
    std::vector<std::string> names;
    for (const CommandSpec& c : command_specs()) names.emplace_back(c.name);
    return usage_error("help", codes::cli::unknown_command,
                       "unknown command '" + name + "'" + did_you_mean(name, names));
  }
  print_command_help(*command, std::cout);
  return kExitOk;
}

const RegisterCommand help_command{"help", run_help};

}  // namespace

}  // namespace fapc::cli

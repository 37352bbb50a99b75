// fapc: one program, subcommands registered by their own files (see registry.hpp).
#include <iostream>
#include <string>
#include <vector>

#include "fapc/commands.hpp"

namespace {

int print_help(std::ostream& out) {
  out << "fapc: the MPEG-4 face animation transcoder\n\nusage:\n";
  for (const auto& [name, command] : fapc::cli::commands()) out << "  " << command.usage << '\n';
  out << "\nSee docs/cli.md for the contract.\n";
  return fapc::cli::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_help(std::cerr);
    return fapc::cli::kExitUsage;
  }
  const std::string name = args.front();
  if (name == "--help" || name == "-h" || name == "help") return print_help(std::cout);
  if (name == "--version") {
    std::cout << "fapc 0.1.0\n";
    return fapc::cli::kExitOk;
  }
  const auto& table = fapc::cli::commands();
  const auto it = table.find(name);
  if (it == table.end()) {
    std::cerr << "fapc: unknown command '" << name << "' (try fapc --help)\n";
    return fapc::cli::kExitUsage;
  }
  args.erase(args.begin());
  return it->second.run(args);
}

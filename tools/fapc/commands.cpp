#include "fapc/commands.hpp"

namespace fapc::cli {

namespace {

// A function-local static: the registering objects of other files may run before this file's
// globals are initialised. (Commands live in the program itself, so a static link keeps them.)
std::map<std::string, Command>& command_table() {
  static std::map<std::string, Command> table;
  return table;
}

}  // namespace

RegisterCommand::RegisterCommand(std::string name, CommandFn run) { command_table()[name] = Command{name, run}; }

const std::map<std::string, Command>& commands() { return command_table(); }

}  // namespace fapc::cli

// The subcommands of the fapc program, each registering itself from its own file, and the one
// table from an error's kind to the exit status (docs/cli.md).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::cli {

// docs/cli.md: exit statuses.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitVerifyFailed = 3;

// The exit status an error of this kind ends the program with.
constexpr int exit_status(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::usage:
      return kExitUsage;
    case ErrorKind::verification_failed:
      return kExitVerifyFailed;
    case ErrorKind::bad_input:
    case ErrorKind::truncated:
    case ErrorKind::io:
    case ErrorKind::limit_exceeded:
    case ErrorKind::unsupported:
      return kExitBadInput;
  }
  return kExitBadInput;
}

// Of two statuses for one run, the one to end with: bad input over a failed verification over
// success (docs/cli.md).
constexpr int worse_status(int a, int b) {
  if (a == kExitBadInput || b == kExitBadInput) return kExitBadInput;
  if (a == kExitUsage || b == kExitUsage) return kExitUsage;
  return a > b ? a : b;
}

using CommandFn = int (*)(const std::vector<std::string>& args);

// What a subcommand does; what it is called and takes is declared in cli_spec.cpp.
struct Command {
  std::string name;
  CommandFn run;
};

struct RegisterCommand {
  RegisterCommand(std::string name, CommandFn run);
};

const std::map<std::string, Command>& commands();

}  // namespace fapc::cli

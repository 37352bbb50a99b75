// A small argument parser for the subcommands: positionals, `--flag`, `--opt VALUE`,
// `--opt=VALUE`, repeatable options, `-o` as an alias for `--output`. Errors are usage errors
// (exit status 2).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fapc::cli {

class Args {
 public:
  // `valued` lists options that take a value, `flags` those that do not (names without "--").
  Args(const std::vector<std::string>& argv, std::set<std::string> valued,
       std::set<std::string> flags);

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }

  const std::vector<std::string>& positionals() const { return positionals_; }
  bool flag(const std::string& name) const { return flags_seen_.count(name) > 0; }
  std::optional<std::string> value(const std::string& name) const;  // the last one given
  std::vector<std::string> values(const std::string& name) const;   // every one, in order
  // An integer option in [low, high]; sets error() when it is not one.
  int integer(const std::string& name, int fallback, int low, int high);
  // A decimal option in [low, high]; empty when absent; sets error() when it is not one.
  std::optional<double> decimal(const std::string& name, double low, double high);
  // Records a usage error (the first one wins).
  void fail(std::string message) {
    if (error_.empty()) error_ = std::move(message);
  }

 private:
  std::vector<std::string> positionals_;
  std::map<std::string, std::vector<std::string>> values_;
  std::set<std::string> flags_seen_;
  std::string error_;
};

// Prints "fapc: USAGE-ERROR" and the command's usage line; returns kExitUsage.
int usage_error(const std::string& command, const std::string& message);

}  // namespace fapc::cli

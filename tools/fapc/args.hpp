// The parser of a subcommand's arguments, driven by the declaration in cli_spec.hpp: positionals
// (with "-" for standard input or output), `--flag`, `--opt VALUE`, `--opt=VALUE`, short names
// (`-o FILE`, `-oFILE`, `-q`), repeatable options, and `--` after which everything is a
// positional. An option the subcommand does not declare is a usage error (exit status 2) with the
// closest spellings suggested.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fapc/cli_codes.hpp"

namespace fapc::cli {

class Args {
 public:
  Args(const std::string& command, const std::vector<std::string>& argv);

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  ErrorCode error_code() const { return error_code_; }  // what error() is (cli_codes.def)

  const std::vector<std::string>& positionals() const { return positionals_; }
  bool flag(const std::string& name) const { return flags_seen_.count(name) > 0; }
  std::optional<std::string> value(const std::string& name) const;  // the last one given
  std::vector<std::string> values(const std::string& name) const;   // every one, in order
  std::vector<std::string> given() const;                           // the options given, by long name, sorted
  // A number option, read as its declaration says (cli_spec.cpp: integer or decimal, in its range):
  // `fallback` (integer) or empty (decimal) when absent; sets error() when out of range, in one
  // shape: "--NAME takes an integer from LOW to HIGH, not 'VALUE'".
  int integer(const std::string& name, int fallback);
  std::optional<double> decimal(const std::string& name);
  // A word option (--ranges fit|max): one of the declared words, or error() "--NAME takes A, B or C,
  // not 'VALUE'"; empty when absent or wrong.
  std::optional<std::string> word(const std::string& name);
  // Records a usage error (the first one wins).
  void fail(ErrorCode code, std::string message) {
    if (!error_.empty()) return;
    error_ = std::move(message);
    error_code_ = code;
  }

 private:
  void take(const std::string& command, const std::vector<std::string>& argv, std::size_t& i);

  std::vector<std::string> positionals_;
  std::map<std::string, std::vector<std::string>> values_;
  std::set<std::string> flags_seen_;
  std::string error_;
  ErrorCode error_code_ = codes::cli::bad_option;
};

// "unknown option --fsp; did you mean --fps?" (and where an option of another subcommand belongs).
std::string unknown_option_message(const std::string& command, const std::string& option);

// Prints "fapc COMMAND: USAGE-ERROR" and the command's usage line; returns kExitUsage.
int usage_error(const std::string& command, ErrorCode code, const std::string& message);
// The same for the error of parsing the command line, or of a library's usage error.
int usage_error(const std::string& command, const Args& args);
int usage_error(const std::string& command, const Diagnostic& error);

}  // namespace fapc::cli

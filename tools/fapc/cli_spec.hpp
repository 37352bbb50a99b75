// The command line, declared once: every subcommand and every option (long and short name, value
// name, help text, the subcommands it applies to). The parser (args.hpp), `--help`, `fapc help`,
// the man page, the bash and zsh completions and the option tables of docs/cli.md are all made
// from these two tables, so none of them can drift from what the program accepts.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fapc::cli {

// What a shell may complete an option's value with.
enum class ValueCompletion { none, file, folder, words, input_kinds, output_kinds, fap_flavours };

// A number's kind: the parser reads it so (Args::integer, Args::decimal) and help names it.
enum class Numeric { none, integer, decimal };

// What an option changes, checked against the pipeline's rows (tests/command/option_rows_test.cpp):
// `reading` options change how an input is read, and the rows of the inputs that read them name
// them (`fapc formats`); given for an input whose row does not, they draw a warning
// (format.option_not_read). `writing` options change what an output holds; outputs' rows name them.
enum class OptionRole { command, reading, writing };

struct OptionSpec {
  std::string_view name{};        // the long form without "--": "fps"
  char short_name = 0;            // 'o' for -o; 0: none
  std::string_view value_name{};  // "N", "FILE"; empty: a flag without value
  std::string_view help{};        // one sentence, no final full stop
  std::string_view commands{};    // the subcommands it applies to, space-separated; "*": all
  bool repeatable = false;        // each use adds a value (--event, --allow-include)
  ValueCompletion completion = ValueCompletion::none;
  std::string_view words{};  // the values for ValueCompletion::words, space-separated
  // The value's type, range and default, set by the builders below (so that a row stays one line
  // of name, help and commands): the parser reads a number within [low, high], and help, the man
  // page and docs/cli.md show the range and the default.
  Numeric numeric = Numeric::none;
  double low = 0;
  double high = 0;
  std::string shown_default{};  // as people read it ("25", "640x480"); empty: none said
  OptionRole role = OptionRole::command;

  // An integer or a decimal number in [low, high].
  OptionSpec integer(double min, double max, std::string default_value = {}) const;
  OptionSpec decimal(double min, double max, std::string default_value = {}) const;
  OptionSpec defaults_to(std::string default_value) const;
  // It changes how inputs are read (or outputs written): the rows of those kinds name it.
  OptionSpec reads() const;
  OptionSpec writes() const;

  bool takes_value() const { return !value_name.empty(); }
  bool applies_to(std::string_view command) const;
  // "-o, --output FILE" or "--fps N".
  std::string label() const;
  // The value's type, range and default for people: "an integer from 1 to 1000; default 25",
  // "one of fit, max; default fit"; empty for a flag or a value without any.
  std::string value_facts() const;
  // The values a word option takes ("fit max"), from the declaration or the tables it names.
  std::string value_words() const;
};

// A number as the parser's messages and help show it: integers in digits, others as printed.
std::string shown_number(double value, Numeric numeric);

struct CommandSpec {
  std::string_view name{};      // "compile"
  std::string_view operands{};  // "INPUT -o OUTPUT"
  std::string_view summary{};   // one line, for lists
  std::string_view details{};   // a paragraph for `fapc help COMMAND` and the man page
};

const std::vector<OptionSpec>& option_specs();
const std::vector<CommandSpec>& command_specs();

const CommandSpec* find_command_spec(std::string_view name);
// The options a subcommand takes, in declaration order.
std::vector<const OptionSpec*> options_of(std::string_view command);
// By long name ("fps") or short ('o' as "o"); null if none.
const OptionSpec* find_option(std::string_view name);
const OptionSpec* find_short_option(char name);

// "fapc compile INPUT -o OUTPUT [options]".
std::string usage_line(const CommandSpec& command);

}  // namespace fapc::cli

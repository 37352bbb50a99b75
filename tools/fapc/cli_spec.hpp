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

struct OptionSpec {
  std::string_view name{};        // the long form without "--": "fps"
  char short_name = 0;            // 'o' for -o; 0: none
  std::string_view value_name{};  // "N", "FILE"; empty: a flag without value
  std::string_view help{};        // one sentence, no final full stop
  std::string_view commands{};    // the subcommands it applies to, space-separated; "*": all
  bool repeatable = false;        // each use adds a value (--event, --allow-include)
  ValueCompletion completion = ValueCompletion::none;
  std::string_view words{};  // the values for ValueCompletion::words, space-separated

  bool takes_value() const { return !value_name.empty(); }
  bool applies_to(std::string_view command) const;
  // "-o, --output FILE" or "--fps N".
  std::string label() const;
};

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

#include "fapc/args.hpp"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <sstream>

#include "fapc/cli_spec.hpp"
#include "fapc/codec/did_you_mean.hpp"
#include "fapc/commands.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

// Whether an argument can only be an operand (docs/cli.md, "Operands"): "-" (standard input or
// output), anything not starting with '-', anything holding a space ("-0.5 * joy.fap": no option
// has one), and a minus sign before a digit or a point (a number: no option starts so).
bool is_operand(const std::string& arg) {
  if (arg.size() < 2 || arg[0] != '-') return true;
  if (arg.find_first_of(" \t\n") != std::string::npos) return true;
  return (arg[1] >= '0' && arg[1] <= '9') || arg[1] == '.';
}

}  // namespace

Args::Args(const std::string& command, const std::vector<std::string>& argv) {
  for (std::size_t i = 0; i < argv.size() && ok(); ++i) {
    // "--" makes the argument after it an operand whatever it looks like; options may follow
    // (`fapc compile -- -odd-name.fap -o x.fap`).
    if (argv[i] == "--") {
      if (++i < argv.size()) positionals_.push_back(argv[i]);
      continue;
    }
    take(command, argv, i);
  }
}

void Args::take(const std::string& command, const std::vector<std::string>& argv, std::size_t& i) {
  const std::string& arg = argv[i];
  if (is_operand(arg)) {
    positionals_.push_back(arg);
    return;
  }
  const OptionSpec* option = nullptr;
  std::optional<std::string> attached;
  if (arg[1] == '-') {
    std::string name = arg.substr(2);
    if (const auto eq = name.find('='); eq != std::string::npos) {
      attached = name.substr(eq + 1);
      name.resize(eq);
    }
    option = find_option(name);
  } else {
    option = find_short_option(arg[1]);
    if (arg.size() > 2) {
      // -oFILE: the rest is the value; -qv and the like are not taken (one letter per argument).
      if (option && option->takes_value()) {
        attached = arg.substr(2);
      } else {
        option = nullptr;
      }
    }
  }
  if (!option || !option->applies_to(command)) {
    fail(codes::cli::unknown_option, unknown_option_message(command, attached ? arg.substr(0, arg.find('=')) : arg));
    return;
  }
  const std::string name(option->name);
  if (!option->takes_value()) {
    if (attached) {
      fail(codes::cli::bad_option, "option --" + name + " takes no value");
      return;
    }
    flags_seen_.insert(name);
    return;
  }
  if (attached) {
    values_[name].push_back(*attached);
  } else if (i + 1 < argv.size()) {
    values_[name].push_back(argv[++i]);
  } else {
    fail(codes::cli::bad_option, "option --" + name + " needs a value (" + std::string(option->value_name) + ")");
  }
}

std::string unknown_option_message(const std::string& command, const std::string& option) {
  std::string message = "unknown option " + option;
  std::string bare = option;
  while (!bare.empty() && bare.front() == '-') bare.erase(bare.begin());
  if (const OptionSpec* elsewhere = bare.size() == 1 ? find_short_option(bare[0]) : find_option(bare)) {
    if (!elsewhere->applies_to(command))
      return message + " (--" + std::string(elsewhere->name) + " is an option of " + std::string(elsewhere->commands) +
             ", not " + command + ")";
  }
  std::vector<std::string> candidates;
  for (const OptionSpec* o : options_of(command)) candidates.push_back("--" + std::string(o->name));
  return message + did_you_mean("--" + bare, candidates);
}

std::optional<std::string> Args::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end() || it->second.empty()) return std::nullopt;
  return it->second.back();
}

std::vector<std::string> Args::values(const std::string& name) const {
  const auto it = values_.find(name);
  return it == values_.end() ? std::vector<std::string>{} : it->second;
}

namespace {

// The declaration of a number option read by name; a name not declared so is the program's own
// mistake, caught by the command tests of that option.
const OptionSpec& numeric_spec(const std::string& name, Numeric numeric) {
  static const OptionSpec undeclared{};
  const OptionSpec* spec = find_option(name);
  return spec && spec->numeric == numeric ? *spec : undeclared;
}

std::string out_of_range(const OptionSpec& spec, const std::string& name, const std::string& given) {
  return "--" + name + " takes " + (spec.numeric == Numeric::integer ? "an integer" : "a number") + " from " +
         shown_number(spec.low, spec.numeric) + " to " + shown_number(spec.high, spec.numeric) + ", not '" + given +
         "'";
}

}  // namespace

std::vector<std::string> Args::given() const {
  std::set<std::string> names = flags_seen_;
  for (const auto& [name, values] : values_) names.insert(name);
  return {names.begin(), names.end()};
}

int Args::integer(const std::string& name, int fallback) {
  const auto text = value(name);
  if (!text) return fallback;
  const OptionSpec& spec = numeric_spec(name, Numeric::integer);
  int parsed = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), parsed);
  if (ec != std::errc{} || end != text->data() + text->size() || parsed < spec.low || parsed > spec.high) {
    fail(codes::cli::bad_option_value, out_of_range(spec, name, *text));
    return fallback;
  }
  return parsed;
}

std::optional<double> Args::decimal(const std::string& name) {
  const auto text = value(name);
  if (!text) return std::nullopt;
  const OptionSpec& spec = numeric_spec(name, Numeric::decimal);
  double parsed = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), parsed);
  if (ec != std::errc{} || end != text->data() + text->size() || !(parsed >= spec.low && parsed <= spec.high)) {
    fail(codes::cli::bad_option_value, out_of_range(spec, name, *text));
    return std::nullopt;
  }
  return parsed;
}

std::optional<std::string> Args::word(const std::string& name) {
  const auto text = value(name);
  if (!text) return std::nullopt;
  const OptionSpec* spec = find_option(name);
  std::vector<std::string> words;
  std::istringstream all(spec ? spec->value_words() : std::string());
  for (std::string w; all >> w;) words.push_back(w);
  if (std::find(words.begin(), words.end(), *text) != words.end()) return text;
  std::string listed;
  for (std::size_t i = 0; i < words.size(); ++i)
    listed += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  fail(codes::cli::bad_option_value, "--" + name + " takes " + listed + ", not '" + *text + "'");
  return std::nullopt;
}

namespace {

// -v names the code (docs/errors.md) as a diagnostic does: "fapc compile: error[cli.operands]: ...".
int print_usage_error(const std::string& command, const std::string& code, const std::string& message) {
  std::cerr << "fapc " << command << ": ";
  if (verbosity() == Verbosity::verbose && !code.empty()) std::cerr << "error[" << code << "]: ";
  std::cerr << message << '\n';
  if (const CommandSpec* spec = find_command_spec(command))
    std::cerr << "usage: " << usage_line(*spec) << " (fapc " << command << " --help lists them)\n";
  return kExitUsage;
}

}  // namespace

int usage_error(const std::string& command, ErrorCode code, const std::string& message) {
  return print_usage_error(command, code.name, message);
}
int usage_error(const std::string& command, const Args& args) {
  return print_usage_error(command, args.error_code().name, args.error());
}
int usage_error(const std::string& command, const Diagnostic& error) {
  return print_usage_error(command, error.code, error.message);
}

}  // namespace fapc::cli

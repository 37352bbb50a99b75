#include "fapc/args.hpp"

#include <charconv>
#include <iostream>
#include <sstream>

#include "fapc/commands.hpp"

namespace fapc::cli {

Args::Args(const std::vector<std::string>& argv, std::set<std::string> valued,
           std::set<std::string> flags) {
  for (std::size_t i = 0; i < argv.size(); ++i) {
    std::string arg = argv[i];
    if (arg == "-o") arg = "--output";
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) {
      positionals_.push_back(argv[i]);  // includes "-" (standard input/output)
      continue;
    }
    std::string name = arg.substr(2);
    std::optional<std::string> inline_value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name.resize(eq);
    }
    if (valued.count(name)) {
      if (inline_value) {
        values_[name].push_back(*inline_value);
      } else if (i + 1 < argv.size()) {
        values_[name].push_back(argv[++i]);
      } else {
        error_ = "option --" + name + " needs a value";
        return;
      }
    } else if (flags.count(name) && !inline_value) {
      flags_seen_.insert(name);
    } else {
      error_ = "unknown option " + arg;
      return;
    }
  }
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

int Args::integer(const std::string& name, int fallback, int low, int high) {
  const auto text = value(name);
  if (!text) return fallback;
  int parsed = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), parsed);
  if (ec != std::errc{} || end != text->data() + text->size() || parsed < low || parsed > high) {
    fail("--" + name + " takes an integer from " + std::to_string(low) + " to " +
         std::to_string(high) + ", not '" + *text + "'");
    return fallback;
  }
  return parsed;
}

std::optional<double> Args::decimal(const std::string& name, double low, double high) {
  const auto text = value(name);
  if (!text) return std::nullopt;
  double parsed = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), parsed);
  if (ec != std::errc{} || end != text->data() + text->size() || !(parsed >= low && parsed <= high)) {
    std::ostringstream message;
    message << "--" << name << " takes a number from " << low << " to " << high << ", not '"
            << *text << "'";
    fail(message.str());
    return std::nullopt;
  }
  return parsed;
}

int usage_error(const std::string& command, const std::string& message) {
  std::cerr << "fapc " << command << ": " << message << '\n';
  const auto it = commands().find(command);
  if (it != commands().end()) std::cerr << "usage: " << it->second.usage << '\n';
  return kExitUsage;
}

}  // namespace fapc::cli

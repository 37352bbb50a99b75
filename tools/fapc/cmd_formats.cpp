// fapc formats [--json]: every reader and writer of the pipeline's registry (kind, extensions,
// what it carries, the options that apply), read from the registry itself.
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "fapc/args.hpp"
#include "fapc/commands.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::cli {

namespace {

std::string joined(const std::vector<std::string>& items, const std::string& prefix, const std::string& separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + prefix + item;
  return out.empty() ? "-" : out;
}

template <class Format>
nlohmann::ordered_json format_json(const Format& f) {
  std::vector<std::string> options;
  for (const std::string& o : f.options) options.push_back("--" + o);
  return {{"kind", f.kind}, {"extensions", f.extensions}, {"carries", f.carries}, {"options", options}};
}

template <class Format>
void print_table(const char* title, const std::vector<Format>& table) {
  std::cout << title << ":\n";
  for (const Format& f : table) {
    std::cout << "  " << std::left << std::setw(10) << f.kind << std::setw(22) << joined(f.extensions, "", " ")
              << f.carries << '\n';
    if (!f.options.empty()) std::cout << std::string(34, ' ') << "options: " << joined(f.options, "--", " ") << '\n';
  }
}

int run_formats(const std::vector<std::string>& argv) {
  Args args("formats", argv);
  if (!args.ok()) return usage_error("formats", args);
  if (!args.positionals().empty()) return usage_error("formats", codes::cli::operands, "takes no operands");
  const pipeline::Registry& registry = pipeline::formats();
  if (args.flag("json")) {
    nlohmann::ordered_json out = {{"inputs", nlohmann::ordered_json::array()},
                                  {"outputs", nlohmann::ordered_json::array()}};
    for (const auto& f : registry.inputs()) out["inputs"].push_back(format_json(f));
    for (const auto& f : registry.outputs()) out["outputs"].push_back(format_json(f));
    std::cout << out.dump(2) << '\n';
    return kExitOk;
  }
  print_table("inputs (the kind comes from the extension, or --from KIND)", registry.inputs());
  std::cout << '\n';
  print_table("outputs (the kind comes from the extension, or --to KIND)", registry.outputs());
  std::cout << "\n- is standard input (with --from) or output (with -o - --to).\n";
  return kExitOk;
}

const RegisterCommand formats_command{"formats", run_formats};

}  // namespace

}  // namespace fapc::cli

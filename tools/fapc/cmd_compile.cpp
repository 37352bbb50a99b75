// fapc compile INPUT -o OUTPUT: any supported input to any supported output.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

// Standard input is saved to a temporary file with the extension of --from, because every
// front end reads a path (and resolves relative includes from it).
std::string save_stdin(const std::string& kind) {
  const pipeline::InputFormat* format = pipeline::formats().input_named(kind);
  if (!format) return {};
  const auto folder = std::filesystem::temp_directory_path() /
                      ("fapc-stdin-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::string path = (folder / ("stdin" + format->extensions.front())).string();
  std::ofstream(path, std::ios::binary) << std::cin.rdbuf();
  return path;
}

int run_compile(const std::vector<std::string>& argv) {
  Args args(argv, [] { auto v = kConvertValued; v.insert("output"); return v; }(), kConvertFlags);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("compile", args.error());
  if (args.positionals().size() != 1) return usage_error("compile", "expected one INPUT");
  const auto output = args.value("output");
  if (!output) return usage_error("compile", "missing -o OUTPUT");
  std::string input = args.positionals().front();
  const std::string to = args.value("to").value_or("");
  if (*output == "-" && to.empty()) return usage_error("compile", "-o - needs --to KIND");
  if (input == "-") {
    const auto from = args.value("from");
    if (!from) return usage_error("compile", "standard input needs --from KIND");
    input = save_stdin(*from);
    if (input.empty()) return usage_error("compile", "unknown input kind '" + *from + "'");
    options.includes.base_folder = ".";  // its includes are named from the working folder
  }
  const pipeline::ConvertResult result = pipeline::convert(input, {{*output, to}}, options);
  const int status = report_outcome(result.warnings, result.error);
  if (status == kExitOk && *output == "-") std::cout << result.standard_output << std::flush;
  if (args.positionals().front() == "-") std::filesystem::remove_all(std::filesystem::path(input).parent_path());
  return status;
}

const RegisterCommand compile_command{
    "compile",
    "fapc compile INPUT -o OUTPUT [--fps N] [--profile FILE] [--event NAME=VALUE]... "
    "[--quant Q] [--speech-rate N] [--strict] [--from KIND] [--to KIND]",
    run_compile};

}  // namespace

}  // namespace fapc::cli

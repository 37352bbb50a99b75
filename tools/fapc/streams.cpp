#include "fapc/streams.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <system_error>

#include "fapc/cli_codes.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace fs = std::filesystem;

StandardInputCopy::~StandardInputCopy() {
  std::error_code ignored;
  if (!folder_.empty()) fs::remove_all(folder_, ignored);
}

std::string StandardInputCopy::path() {
  if (!path_.empty()) return path_;
  std::error_code error;
  std::string pattern = (fs::temp_directory_path(error) / "fapc-stdin-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) return {};
  folder_ = pattern;
  path_ = (folder_ / "stdin").string();
  std::ofstream(path_, std::ios::binary) << std::cin.rdbuf();
  return path_;
}

std::optional<std::string> resolve_input(Args& args, std::string& operand, pipeline::ConvertOptions& options,
                                         StandardInputCopy& copy) {
  if (const auto from = args.value("from")) {
    if (!pipeline::formats().input_named(*from)) return pipeline::unknown_kind_message(*from, false);
    options.input_kind = *from;
  }
  if (operand != "-") return std::nullopt;
  if (options.input_kind.empty()) return "standard input needs --from KIND";
  operand = copy.path();
  if (operand.empty()) return "cannot make a temporary folder for standard input";
  options.includes.base_folder = ".";  // its includes are named from the working folder
  show_file_as(operand, "-");
  tell("read standard input as " + options.input_kind);
  return std::nullopt;
}

std::string output_kind(Args& args, const std::string& output, const std::string& default_kind) {
  const auto to = args.value("to");
  if (!to) {
    if (output == "-" && default_kind.empty()) args.fail(codes::cli::bad_option_value, "-o - needs --to KIND");
    return default_kind;
  }
  return *to;  // an unknown kind is the writer's error (unsupported, with the closest kinds)
}

bool write_standard_output(const std::string& bytes) {
  std::cout.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  std::cout.flush();
  if (std::cout) return true;
  report(make_error(
      codes::cli::standard_output_closed, Location::whole_file("<standard output>"),
      std::string("cannot write: ") + std::strerror(errno ? errno : EPIPE) + " (the reading end of the pipe closed)"));
  return false;
}

}  // namespace fapc::cli

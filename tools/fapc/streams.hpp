// Standard input and output for every subcommand (docs/cli.md, "Pipes"): "-" as an input is
// standard input, read as the kind --from names; "-o -" is standard output, as the kind --to
// names. Writing to a pipe whose reader has gone is an I/O error (exit status 1) with a message,
// never a death by SIGPIPE: main() ignores the signal, so no temporary file is left behind.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "fapc/args.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::cli {

// Standard input saved to a private temporary folder (the readers read paths), removed with this.
class StandardInputCopy {
 public:
  StandardInputCopy() = default;
  ~StandardInputCopy();
  StandardInputCopy(const StandardInputCopy&) = delete;
  StandardInputCopy& operator=(const StandardInputCopy&) = delete;
  // The path of the copy (made on the first call).
  std::string path();

 private:
  std::filesystem::path folder_;
  std::string path_;
};

// The input to hand to the pipeline for the operand `operand`: itself, or a copy of standard
// input for "-". Reads --from into options.input_kind (an unknown kind is a usage error with the
// closest kinds); a script read from standard input takes its includes' relative names from the
// working folder. Returns the usage error's message on failure.
std::optional<std::string> resolve_input(Args& args, std::string& operand, pipeline::ConvertOptions& options,
                                         StandardInputCopy& copy);

// The output kind --to names, or `default_kind` when absent (empty: from the output's extension).
// -o - without --to and without a default is a usage error, recorded in args.
std::string output_kind(Args& args, const std::string& output, const std::string& default_kind = "");

// Writes `bytes` to standard output and flushes; false (with the error reported) when the pipe
// is closed.
bool write_standard_output(const std::string& bytes);

}  // namespace fapc::cli

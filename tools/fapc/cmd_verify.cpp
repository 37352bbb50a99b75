// fapc verify FILE... [--quant Q] [--intra-period N] [--ranges fit|max] [--masks fit|keep] [--json]:
// the checks of fapc::pipeline::verify (see fapc/pipeline/verify.hpp), one line or JSON object
// per file. Exit 3 when a check fails, 1 when an input cannot be read.
#include <iostream>

#include <nlohmann/json.hpp>

#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/json_output.hpp"
#include "fapc/pipeline/verify.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

int run_verify(const std::vector<std::string>& argv) {
  Args args("verify", argv);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("verify", args);
  if (args.positionals().empty()) return usage_error("verify", codes::cli::operands, "expected at least one FILE");
  int status = kExitOk;
  std::vector<nlohmann::ordered_json> results;
  StandardInputCopy copy;
  for (const std::string& path : args.positionals()) {
    std::string input = path;
    if (const auto error = resolve_input(args, input, options, copy))
      return usage_error("verify", codes::cli::standard_input, *error);
    const pipeline::VerifyResult verified = pipeline::verify(input, options);
    const int file_status = report_outcome(verified.warnings, verified.error);
    status = worse_status(status, file_status);
    if (args.flag("json")) {
      results.push_back(pipeline::verify_file_json(path, verified, file_status));
    } else if (verified.ok()) {
      std::cout << path << ": ok: " << verified.summary << '\n';
    }
  }
  if (args.flag("json")) std::cout << pipeline::verify_document(std::move(results)).dump(2) << '\n';
  return status;
}

const RegisterCommand verify_command{"verify", run_verify};

}  // namespace

}  // namespace fapc::cli

// fapc compile INPUT -o OUTPUT: any supported input to any supported output.
#include "fapc/commands.hpp"
#include "fapc/conversion.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

int run_compile(const std::vector<std::string>& argv) {
  Args args("compile", argv);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("compile", args);
  if (args.positionals().size() != 1) return usage_error("compile", codes::cli::operands, "expected one INPUT");
  const auto output = args.value("output");
  if (!output) return usage_error("compile", codes::cli::missing_output, "missing -o OUTPUT");
  const std::string to = output_kind(args, *output);
  if (!args.ok()) return usage_error("compile", args);
  std::string input = args.positionals().front();
  StandardInputCopy copy;
  if (const auto error = resolve_input(args, input, options, copy))
    return usage_error("compile", codes::cli::standard_input, *error);
  return convert_one(args.positionals().front(), input, *output, to, options);
}

const RegisterCommand compile_command{"compile", run_compile};

}  // namespace

}  // namespace fapc::cli

// fapc decode IN.fba|IN.mp4 -o OUT.fap: a stream back to frames, written as any output kind
// (normally .fap).
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/report.hpp"

#include <iostream>

namespace fapc::cli {

namespace {

int run_decode(const std::vector<std::string>& argv) {
  Args args(argv, {"output", "to", "fap-flavour"}, {"strict"});
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("decode", args.error());
  if (args.positionals().size() != 1) return usage_error("decode", "expected one input stream");
  const auto output = args.value("output");
  if (!output) return usage_error("decode", "missing -o OUT.fap");
  const std::string& input = args.positionals().front();
  const pipeline::InputFormat* format = pipeline::formats().input_for(input);
  if (format && format->kind != "fba" && format->kind != "mp4")
    return usage_error("decode", "decode reads .fba or .mp4 streams; use compile for '" + input + "'");
  const pipeline::ConvertResult result = pipeline::convert(input, {{*output, args.value("to").value_or("")}}, options);
  const int status = report_outcome(result.warnings, result.error);
  if (status == kExitOk && *output == "-") std::cout << result.standard_output << std::flush;
  return status;
}

const RegisterCommand decode_command{"decode", "fapc decode IN.fba|IN.mp4 -o OUT.fap [--strict] [--to KIND] [--fap-flavour F]",
                                     run_decode};

}  // namespace

}  // namespace fapc::cli

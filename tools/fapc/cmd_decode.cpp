// fapc decode IN.fba|IN.mp4 -o OUT.fap: a stream back to frames, written as any output kind
// (normally .fap).
#include "fapc/commands.hpp"
#include "fapc/conversion.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

int run_decode(const std::vector<std::string>& argv) {
  Args args("decode", argv);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("decode", args);
  if (args.positionals().size() != 1) return usage_error("decode", codes::cli::operands, "expected one input stream");
  const auto output = args.value("output");
  if (!output) return usage_error("decode", codes::cli::missing_output, "missing -o OUT.fap");
  const std::string to = output_kind(args, *output, "fap");
  std::string input = args.positionals().front();
  StandardInputCopy copy;
  if (const auto error = resolve_input(args, input, options, copy))
    return usage_error("decode", codes::cli::standard_input, *error);
  const pipeline::InputFormat* format = pipeline::reader_for(input, options);
  if (format && !format->verify_stream)
    return usage_error("decode", codes::cli::input_kind,
                       "decode reads FBA streams (" +
                           pipeline::extension_list(pipeline::inputs_where(
                               [](const pipeline::InputFormat& f) { return bool(f.verify_stream); })) +
                           "); use compile for '" + args.positionals().front() + "'");
  // Without --to the output's extension decides, as it always has; -o - writes .fap text.
  return convert_one(args.positionals().front(), input, *output, args.value("to") || *output == "-" ? to : "", options);
}

const RegisterCommand decode_command{"decode", run_decode};

}  // namespace

}  // namespace fapc::cli

// fapc encode IN -o OUT.fba [--quant Q] [--intra-period N] [--ranges fit|max] [--masks fit|keep] [--align-planes]
// [--verify]: any input to a raw FBA stream, with the encoder's settings in view.
#include "fapc/codec/file_io.hpp"
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

int run_encode(const std::vector<std::string>& argv) {
  Args args("encode", argv);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("encode", args);
  if (args.positionals().size() != 1) return usage_error("encode", codes::cli::operands, "expected one input file");
  const auto output = args.value("output");
  if (!output) return usage_error("encode", codes::cli::missing_output, "missing -o OUT.fba");
  // An output that cannot be written is refused before the work (it is checked again when written).
  if (auto writable = check_output_path(*output); !writable) return report_outcome({}, writable.error());
  std::string input = args.positionals().front();
  StandardInputCopy copy;
  if (const auto error = resolve_input(args, input, options, copy))
    return usage_error("encode", codes::cli::standard_input, *error);

  auto loaded = pipeline::load(input, options);
  if (!loaded) return report_outcome({}, loaded.error());
  report_all(loaded->warnings);
  auto encoded = pipeline::encode_checked(*loaded, options, input, args.flag("align-planes"));
  if (!encoded) return report_outcome({}, encoded.error());
  const std::string bytes(encoded->bytes.begin(), encoded->bytes.end());
  tell("read " + args.positionals().front() + " (" + std::to_string(loaded->frames.frames.size()) + " frames); " +
       std::to_string(bytes.size()) + " bytes of FBA for " + *output);
  if (*output == "-") return write_standard_output(bytes) ? kExitOk : kExitBadInput;
  if (auto written = write_file_atomic(*output, bytes); !written) return report_outcome({}, written.error());
  return kExitOk;
}

const RegisterCommand encode_command{"encode", run_encode};

}  // namespace

}  // namespace fapc::cli

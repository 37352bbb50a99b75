// fapc plot INPUT -o OUT.svg [--per-clip]: the blended curves, and with --per-clip every action's
// own curve labelled by its source line (Mimic Figure 1, docs/mimic.md).
#include <filesystem>

#include "fapc/codec/file_io.hpp"
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/pipeline/svg_plot.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

int run_plot(const std::vector<std::string>& argv) {
  Args args("plot", argv);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("plot", args.error());
  if (args.positionals().size() != 1) return usage_error("plot", "expected one INPUT");
  const auto output = args.value("output");
  if (!output) return usage_error("plot", "missing -o OUT.svg");
  // A plot is SVG; --to says so for -o - (and is checked, so that --to png fails here, not later).
  const std::string to = output_kind(args, *output, "svg");
  if (to != "svg") return usage_error("plot", "plot writes svg, not '" + to + "'");
  std::string input = args.positionals().front();
  StandardInputCopy copy;
  if (const auto error = resolve_input(args, input, options, copy)) return usage_error("plot", *error);

  Result<pipeline::Loaded> loaded = pipeline::load(input, options);
  if (!loaded) return report_outcome({}, loaded.error());
  report_all(loaded->warnings);
  const std::string& named = args.positionals().front();
  auto svg = pipeline::plot_loaded(*loaded, input, std::filesystem::path(named).filename().string(),
                                   args.flag("per-clip"), options.fps);
  if (!svg) return report_outcome({}, svg.error());
  tell("read " + named + " (" + std::to_string(loaded->frames.frames.size()) + " frames); plot for " + *output);
  if (*output == "-") return write_standard_output(*svg) ? kExitOk : kExitBadInput;
  if (auto written = write_file_atomic(*output, *svg); !written) return report_outcome({}, written.error());
  return kExitOk;
}

const RegisterCommand plot_command{"plot", run_plot};

}  // namespace

}  // namespace fapc::cli

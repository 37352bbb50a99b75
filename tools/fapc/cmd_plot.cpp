// fapc plot INPUT -o OUT.svg|.png|.pdf|.csv [--faps LIST] [--overlay] [--per-clip] [--title TEXT]:
// the curves of any input as a figure (fapc::pipeline::plot_loaded); -o - writes standard output
// (SVG unless --to says otherwise).
#include <filesystem>
#include <iostream>

#include "fapc/codec/file_io.hpp"
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/plot.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

int run_plot(const std::vector<std::string>& argv) {
  Args args("plot", argv);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("plot", args);
  if (args.positionals().size() != 1) return usage_error("plot", codes::cli::operands, "expected one INPUT");
  const auto output = args.value("output");
  if (!output) return usage_error("plot", codes::cli::missing_output, "missing -o OUT (.svg, .png, .pdf or .csv)");
  // --to names the kind as an extension would; -o - without it is SVG.
  const std::string to = output_kind(args, *output, *output == "-" ? "svg" : "");
  pipeline::PlotKind kind{};
  if (!pipeline::plot_kind_for(to.empty() ? *output : "x." + to, kind))
    return usage_error("plot", codes::cli::output_kind,
                       "the output must be .svg, .png, .pdf or .csv: '" + (to.empty() ? *output : to) + "'");
  // An output that cannot be written is refused before the work (it is checked again when written).
  if (auto writable = check_output_path(*output); !writable) return report_outcome({}, writable.error());
  std::string input = args.positionals().front();
  StandardInputCopy copy;
  if (const auto error = resolve_input(args, input, options, copy))
    return usage_error("plot", codes::cli::standard_input, *error);

  // A .csv is the frames as a table; the other plots draw a script's curves, or the frames of an
  // input without a timeline (which always has them).
  options.curves = kind != pipeline::PlotKind::csv;
  options.frames = kind == pipeline::PlotKind::csv;
  Result<pipeline::Loaded> loaded = pipeline::load(input, options);
  if (!loaded) return report_outcome({}, loaded.error());
  report_all(loaded->warnings);
  const std::string& named = args.positionals().front();
  pipeline::PlotOptions plot_options;
  plot_options.title = args.value("title").value_or(std::filesystem::path(named).filename().string());
  plot_options.faps = args.value("faps").value_or("");
  plot_options.overlay = args.flag("overlay");
  plot_options.per_clip = args.flag("per-clip");
  plot_options.fps = options.fps;
  auto plot = pipeline::plot_loaded(*loaded, input, kind, plot_options);
  if (!plot) return report_outcome({}, plot.error());
  if (verbosity() != Verbosity::quiet)
    for (const std::string& note : plot->notes) std::cerr << "fapc plot: note: " << note << '\n';
  tell("read " + named + " (" + std::to_string(pipeline::frames_seen(*loaded).count) + " frames); plot for " + *output);
  if (*output == "-") return write_standard_output(plot->bytes) ? kExitOk : kExitBadInput;
  if (auto written = write_file_atomic(*output, plot->bytes); !written) return report_outcome({}, written.error());
  return kExitOk;
}

const RegisterCommand plot_command{"plot", run_plot};

}  // namespace

}  // namespace fapc::cli

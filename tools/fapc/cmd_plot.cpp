// fapc plot INPUT -o OUT.{svg,png,pdf,csv} [--faps LIST] [--overlay] [--per-clip] [--title TEXT]:
// the curves as a figure (fapc::pipeline::plot_loaded), the format chosen by OUT's extension;
// with --per-clip every action's own curve labelled by its source line (Mimic Figure 1,
// docs/mimic.md).
#include <filesystem>
#include <iostream>

#include "fapc/codec/file_io.hpp"
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/plot.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

int run_plot(const std::vector<std::string>& argv) {
  Args args(argv, [] { auto v = kConvertValued; v.insert({"output", "faps", "title"}); return v; }(),
            [] { auto f = kConvertFlags; f.insert({"per-clip", "overlay"}); return f; }());
  const ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("plot", args.error());
  if (args.positionals().size() != 1) return usage_error("plot", "expected one INPUT");
  const auto output = args.value("output");
  if (!output) return usage_error("plot", "missing -o OUT (.svg, .png, .pdf or .csv)");
  pipeline::PlotKind kind{};
  if (!pipeline::plot_kind_for(*output, kind))
    return usage_error("plot", "the output must end in .svg, .png, .pdf or .csv: '" + *output + "'");
  const std::string& input = args.positionals().front();

  Result<pipeline::Loaded> loaded = pipeline::load(input, options);
  if (!loaded) return report_outcome({}, loaded.error());
  report_all(loaded->warnings);
  pipeline::PlotOptions plot_options;
  plot_options.title = args.value("title").value_or(std::filesystem::path(input).filename().string());
  plot_options.faps = args.value("faps").value_or("");
  plot_options.overlay = args.flag("overlay");
  plot_options.per_clip = args.flag("per-clip");
  plot_options.fps = options.fps;
  auto plot = pipeline::plot_loaded(*loaded, input, kind, plot_options);
  if (!plot) return report_outcome({}, plot.error());
  for (const std::string& note : plot->notes) std::cerr << "fapc plot: note: " << note << '\n';
  if (auto written = write_file_atomic(*output, plot->bytes); !written) return report_outcome({}, written.error());
  return kExitOk;
}

const RegisterCommand plot_command{
    "plot",
    "fapc plot INPUT -o OUT.svg|.png|.pdf|.csv [--faps LIST] [--overlay] [--per-clip] [--title TEXT] [--fps N] "
    "[--profile FILE]",
    run_plot};

}  // namespace

}  // namespace fapc::cli

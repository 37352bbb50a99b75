// fapc plot INPUT -o OUT.svg [--per-clip]: the blended curves, and with --per-clip every action's
// own curve labelled by its source line (Mimic Figure 1, docs/mimic.md).
#include <filesystem>

#include "fapc/codec/file_io.hpp"
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/pipeline/svg_plot.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

int run_plot(const std::vector<std::string>& argv) {
  Args args(argv, [] { auto v = kConvertValued; v.insert("output"); return v; }(),
            [] { auto f = kConvertFlags; f.insert("per-clip"); return f; }());
  const ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("plot", args.error());
  if (args.positionals().size() != 1) return usage_error("plot", "expected one INPUT");
  const auto output = args.value("output");
  if (!output) return usage_error("plot", "missing -o OUT.svg");
  const std::string& input = args.positionals().front();

  Result<pipeline::Loaded> loaded = pipeline::load(input, options);
  if (!loaded) return report_outcome({}, loaded.error());
  report_all(loaded->warnings);
  auto svg = pipeline::plot_loaded(*loaded, input, std::filesystem::path(input).filename().string(),
                                   args.flag("per-clip"), options.fps);
  if (!svg) return report_outcome({}, svg.error());
  if (auto written = write_file_atomic(*output, *svg); !written) return report_outcome({}, written.error());
  return kExitOk;
}

const RegisterCommand plot_command{"plot", "fapc plot INPUT -o OUT.svg [--per-clip] [--fps N] [--profile FILE]",
                                   run_plot};

}  // namespace

}  // namespace fapc::cli

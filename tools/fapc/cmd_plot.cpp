// fapc plot INPUT -o OUT.svg [--per-clip]: the blended curves, and with --per-clip every action's
// own curve labelled by its source line (Mimic Figure 1, docs/mimic.md).
#include <filesystem>

#include "fapc/codec/file_io.hpp"
#include "fapc/convert.hpp"
#include "fapc/report.hpp"
#include "fapc/svg_plot.hpp"
#include "fapc/transcoder/render.hpp"

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

  Result<Loaded> loaded = load_input(input, options);
  if (!loaded) {
    report(loaded.error());
    return kExitBadInput;
  }
  report_all(loaded->warnings);
  std::optional<Curves> per_clip;
  if (args.flag("per-clip")) {
    if (!loaded->timeline) {
      report(make_error(Location{input, 0, 0, -1},
                        "--per-clip needs a timeline input (Mimic, FML or XMT-Omega); this input "
                        "has frames only"));
      return kExitBadInput;
    }
    per_clip = render_clip_curves(*loaded->timeline, CurveOptions{options.fps, 1e-6});
  }
  const Curves blended = loaded->curves ? *loaded->curves : curves_from_frames(loaded->frames);
  const std::string svg = plot_svg(blended, per_clip ? &*per_clip : nullptr,
                                   std::filesystem::path(input).filename().string());
  if (auto written = write_file_atomic(*output, svg); !written) {
    report(written.error());
    return kExitBadInput;
  }
  return kExitOk;
}

const RegisterCommand plot_command{"plot", "fapc plot INPUT -o OUT.svg [--per-clip] [--fps N] [--profile FILE]",
                                   run_plot};

}  // namespace

}  // namespace fapc::cli

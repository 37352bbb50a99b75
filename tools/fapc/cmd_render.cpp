// fapc render INPUT -o OUT.png|.webm|.html: any input shown as a face (docs/render.md).
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

int run_render(const std::vector<std::string>& argv) {
  Args args(argv, [] { auto v = kConvertValued; v.insert("output"); return v; }(), kConvertFlags);
  const ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("render", args.error());
  if (args.positionals().size() != 1) return usage_error("render", "expected one INPUT");
  const PictureSettings& picture = options.picture;
  if (picture.frame && picture.time) return usage_error("render", "give --frame or --time, not both");
  if (picture.sheet && (picture.frame || picture.time))
    return usage_error("render", "--sheet picks its own frames; drop --frame/--time");
  const auto output = args.value("output");
  if (!output) return usage_error("render", "missing -o OUT.png, OUT.webm or OUT.html");
  const pipeline::OutputFormat* format = pipeline::formats().output_for(*output);
  if (!format || (format->kind != "png" && format->kind != "webm" && format->kind != "html"))
    return usage_error("render", "the output must end in .png, .webm or .html: '" + *output + "'");
  const pipeline::ConvertResult result =
      pipeline::convert(args.positionals().front(), {{*output, ""}}, options);
  return report_outcome(result.warnings, result.error);
}

const RegisterCommand render_command{
    "render",
    "fapc render INPUT -o OUT.png|OUT.webm|OUT.html [--size WxH] [--frame K | --time T | --sheet N] "
    "[--frame-rate N] [--points] [--fps N] [--profile FILE]",
    run_render};

}  // namespace

}  // namespace fapc::cli

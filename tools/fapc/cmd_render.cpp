// fapc render INPUT -o OUT.png|.webm|.html: any input shown as a face (docs/render.md).
#include "fapc/commands.hpp"
#include "fapc/conversion.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

int run_render(const std::vector<std::string>& argv) {
  Args args("render", argv);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("render", args.error());
  if (args.positionals().size() != 1) return usage_error("render", "expected one INPUT");
  const PictureSettings& picture = options.picture;
  if (picture.frame && picture.time) return usage_error("render", "give --frame or --time, not both");
  if (picture.sheet && (picture.frame || picture.time))
    return usage_error("render", "--sheet picks its own frames; drop --frame/--time");
  const auto output = args.value("output");
  if (!output) return usage_error("render", "missing -o OUT.png, OUT.webm, OUT.html, OUT.glb or OUT.gltf");
  const std::string to = output_kind(args, *output);
  if (!args.ok()) return usage_error("render", args.error());
  const pipeline::OutputFormat* format =
      to.empty() ? pipeline::formats().output_for(*output) : pipeline::formats().output_named(to);
  const auto face_kind = [](const std::string& kind) {
    return kind == "png" || kind == "webm" || kind == "html" || kind == "glb" || kind == "gltf";
  };
  if (!format || !face_kind(format->kind))
    return usage_error("render", "the output must end in .png, .webm, .html, .glb or .gltf: '" + *output + "'");
  std::string input = args.positionals().front();
  StandardInputCopy copy;
  if (const auto error = resolve_input(args, input, options, copy)) return usage_error("render", *error);
  return convert_one(args.positionals().front(), input, *output, to, options);
}

const RegisterCommand render_command{"render", run_render};

}  // namespace

}  // namespace fapc::cli

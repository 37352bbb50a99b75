// fapc render INPUT -o OUT.png|.webm|.html: any input shown as a face (docs/render.md).
#include "fapc/commands.hpp"
#include "fapc/conversion.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

int run_render(const std::vector<std::string>& argv) {
  Args args("render", argv);
  ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("render", args);
  if (args.positionals().size() != 1) return usage_error("render", codes::cli::operands, "expected one INPUT");
  const PictureSettings& picture = options.picture;
  if (picture.frame && picture.time)
    return usage_error("render", codes::cli::conflicting_options, "give --frame or --time, not both");
  if (picture.sheet && (picture.frame || picture.time))
    return usage_error("render", codes::cli::conflicting_options, "--sheet picks its own frames; drop --frame/--time");
  const auto output = args.value("output");
  if (!output)
    return usage_error("render", codes::cli::missing_output, "missing -o OUTPUT (a picture: fapc formats lists them)");
  const std::string to = output_kind(args, *output);
  if (!args.ok()) return usage_error("render", args);
  const pipeline::OutputFormat* format =
      to.empty() ? pipeline::formats().output_for(*output) : pipeline::formats().output_named(to);
  if (!format || !format->picture)
    return usage_error("render", codes::cli::output_kind,
                       "the output must end in " +
                           pipeline::extension_list(
                               pipeline::outputs_where([](const pipeline::OutputFormat& f) { return f.picture; })) +
                           ": '" + *output + "'");
  std::string input = args.positionals().front();
  StandardInputCopy copy;
  if (const auto error = resolve_input(args, input, options, copy))
    return usage_error("render", codes::cli::standard_input, *error);
  return convert_one(args.positionals().front(), input, *output, to, options);
}

const RegisterCommand render_command{"render", run_render};

}  // namespace

}  // namespace fapc::cli

// fapc combine EXPRESSION -o OUT: the Algebra of Expressions over files (docs/algebra.md).
// fapc combine --states EXPRESSION [--frame K]: one state as 66 integers, for checking by hand.
#include <filesystem>
#include <iostream>

#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/combine.hpp"
#include "fapc/pipeline/convert.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

using algebra::Value;

int print_state(const Value& value, const Args& args) {
  const algebra::FacialState* state = value.state ? &*value.state : nullptr;
  const auto& frames = value.animation.frames;
  const auto frame = args.value("frame");
  std::size_t k = 0;
  if (!state && frame) k = std::strtoull(frame->c_str(), nullptr, 10);
  if (!state && !frame && frames.size() != 1) {
    std::cerr << "fapc combine: the expression is an animation of " << frames.size()
              << " frames; --states prints one state (pick one with --frame K)\n";
    return kExitUsage;
  }
  if (!state && k < frames.size() && frames[k]) state = &*frames[k];
  if (!state) {
    std::cerr << "fapc combine: the animation has no frame " << k << "\n";
    return kExitUsage;
  }
  for (std::size_t i = 0; i < state->values.size(); ++i) {
    std::cout << (i ? " " : "") << state->values[i];
  }
  std::cout << '\n';
  return kExitOk;
}

int run_combine(const std::vector<std::string>& argv) {
  Args args("combine", argv);
  const ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("combine", args);
  if (args.positionals().size() != 1)
    return usage_error("combine", codes::cli::operands, "expected one EXPRESSION (quote it)");
  const bool states = args.flag("states");
  const auto output = args.value("output");
  if (!states && !output) return usage_error("combine", codes::cli::missing_output, "missing -o OUTPUT (or --states)");
  Diagnostics warnings;
  Result<Value> value = pipeline::evaluate_combination(args.positionals().front(), "", options, warnings);
  if (!value) return report_outcome(warnings, value.error());
  report_all(warnings);
  if (states) return print_state(*value, args);
  pipeline::Loaded loaded;
  loaded.origin = "<expression>";  // what errors about the frames name, as expression errors do
  loaded.frames = pipeline::frames_of(*value, options.fps, std::filesystem::path(*output).stem().string());
  const std::string to = output_kind(args, *output);
  if (!args.ok()) return usage_error("combine", args);
  const pipeline::ConvertResult result = pipeline::write_outputs(std::move(loaded), {{*output, to}}, options);
  const int status = report_outcome({}, result.error);
  if (status == kExitOk && *output == "-" && !write_standard_output(result.standard_output)) return kExitBadInput;
  return status;
}

const RegisterCommand combine_command{"combine", run_combine};

}  // namespace

}  // namespace fapc::cli

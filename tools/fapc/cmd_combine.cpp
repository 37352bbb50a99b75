// fapc combine EXPRESSION -o OUT: the Algebra of Expressions over files (docs/algebra.md).
// fapc combine --states EXPRESSION [--frame K]: one state as 66 integers, for checking by hand.
#include <filesystem>
#include <iostream>

#include "fapc/codec/file_io.hpp"
#include "fapc/convert.hpp"
#include "fapc/report.hpp"
#include "fapc/timeline_input.hpp"
#include "fapc/transcoder/algebra_expression.hpp"

namespace fapc::cli {

namespace {

using algebra::Value;

Result<Value> load_operand(const std::string& name, const ConvertOptions& options,
                           const Profile& profile) {
  Value value;
  if (name.ends_with(".xpr")) {  // a facial state
    Result<std::string> text = read_file_bytes(name);
    if (!text) return text.error();
    Result<std::vector<ExpressionEntry>> entries = parse_expression_file(*text, name);
    if (!entries) return entries.error();
    Result<algebra::FacialState> state = algebra::state_from_entries(*entries, profile);
    if (!state) return state.error();
    value.state = *state;
    return value;
  }
  Result<Loaded> loaded = load_input(name, options);
  if (!loaded) return loaded.error();
  report_all(loaded->warnings);
  value.animation = algebra::animation_from(loaded->frames);
  return value;
}

// The result as frames: a state is one frame.
FapSequence frames_of(const Value& value, int fps, const std::string& name) {
  algebra::Animation animation = value.animation;
  if (value.state) {
    animation.fps = fps;
    animation.frames = {*value.state};
    for (int fap = 3; fap <= 68; ++fap) {
      if (value.state->at(fap) != 0) animation.carried.set(static_cast<std::size_t>(fap - 3));
    }
  }
  return algebra::sequence_from(animation, name);
}

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
  Args args(argv, [] { auto v = kConvertValued; v.insert("output"); v.insert("frame"); return v; }(),
            [] { auto f = kConvertFlags; f.insert("states"); return f; }());
  const ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("combine", args.error());
  if (args.positionals().size() != 1) return usage_error("combine", "expected one EXPRESSION (quote it)");
  const bool states = args.flag("states");
  const auto output = args.value("output");
  if (!states && !output) return usage_error("combine", "missing -o OUTPUT (or --states)");
  Result<Profile> profile = profile_for(options);
  if (!profile) {
    report(profile.error());
    return kExitBadInput;
  }
  const auto load = [&](const std::string& name, int) { return load_operand(name, options, *profile); };
  Result<Value> value = algebra::evaluate(args.positionals().front(), load);
  if (!value) {
    report(value.error());
    return kExitBadInput;
  }
  if (states) return print_state(*value, args);
  Loaded loaded;
  loaded.frames = frames_of(*value, options.fps, std::filesystem::path(*output).stem().string());
  return write_output(loaded, *output, options, args.value("to").value_or(""));
}

const RegisterCommand combine_command{
    "combine",
    "fapc combine EXPRESSION -o OUTPUT [--profile FILE] [--to KIND] | fapc combine --states "
    "EXPRESSION [--frame K]",
    run_combine};

}  // namespace

}  // namespace fapc::cli

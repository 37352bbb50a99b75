#include "fapc/pipeline/combine.hpp"

#include "fapc/codec/file_io.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/transcoder/expression_file.hpp"
#include "input_chain.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline {

namespace {

// A facial state (.xpr) or, through the registry, any input; an included one (an operand of a
// .combine file) is checked for cycles and read on a stack of its own.
Result<algebra::Value> load_operand(const std::string& path, const Location& where, bool included,
                                    const ConvertOptions& options, const Profile& profile,
                                    Diagnostics& warnings) {
  algebra::Value value;
  if (path.ends_with(".xpr")) {
    Result<std::string> text = read_file_bytes(path);
    if (!text) return text.error();
    Result<std::vector<ExpressionEntry>> entries = parse_expression_file(*text, path);
    if (!entries) return entries.error();
    Result<algebra::FacialState> state = algebra::state_from_entries(*entries, profile);
    if (!state) return state.error();
    value.state = *state;
    return value;
  }
  Result<Loaded> loaded = included ? load_included_input(path, where, options) : load(path, options);
  if (!loaded) return loaded.error();
  warnings.insert(warnings.end(), loaded->warnings.begin(), loaded->warnings.end());
  value.animation = algebra::animation_from(loaded->frames);
  return value;
}

}  // namespace

Result<algebra::Value> evaluate_combination(const std::string& expression,
                                            const std::string& including_file,
                                            const ConvertOptions& options, Diagnostics& warnings) {
  Result<Profile> profile = profile_for(options);
  if (!profile) return profile.error();
  ConvertOptions operands = options;  // operands are frames, whoever asks for the combination
  operands.render = true;
  operands.facts = false;
  const auto load_file = [&](const std::string& name, int column) -> Result<algebra::Value> {
    const Location where = Location::text("<expression>", 1, column);
    if (including_file.empty()) return load_operand(name, where, false, operands, *profile, warnings);
    Result<std::string> path = resolve_include(name, including_file, operands.includes, where);
    if (!path) return path.error();
    return load_operand(*path, where, true, operands, *profile, warnings);
  };
  return algebra::evaluate(expression, load_file);
}

FapSequence frames_of(const algebra::Value& value, int fps, const std::string& name) {
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

}  // namespace fapc::pipeline

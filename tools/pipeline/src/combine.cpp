#include "fapc/pipeline/combine.hpp"

#include "fapc/codec/file_io.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/transcoder/expression_file.hpp"
#include "input_chain.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline {

namespace {

// A facial state (.xpr) or, through the registry, any input; an included one (an operand of a
// .combine file) is checked for cycles and read on a stack of its own.
Result<algebra::Value> load_operand(const std::string& path, const Location& where, bool included,
                                    const ConvertOptions& options, const Profile& profile, Diagnostics& warnings) {
  algebra::Value value;
  if (path.ends_with(".xpr")) {
    Result<std::string> text = read_file_bytes(path, options.limits);
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
  // The Algebra's grid has a slot for every frame from 0 to the last: frames before 0 have no
  // slot, and a late last frame costs as much as a long animation.
  if (const auto& frames = loaded->frames.frames; !frames.empty()) {
    if (frames.front().number < 0)
      return make_error(codes::combine::before_zero, Location::whole_file(path),
                        "frame " + std::to_string(frames.front().number) +
                            " is before time 0: an operand's frames start at 0 or later");
    if (frames.back().number >= options.limits.max_frames)
      return limit_error(Location::whole_file(path),
                         "its frames run to number " + std::to_string(frames.back().number) + ", a grid of " +
                             std::to_string(frames.back().number + 1) + " frames",
                         Limit::frames, options.limits);
  }
  value.animation = algebra::animation_from(loaded->frames);
  return value;
}

}  // namespace

Result<algebra::Value> evaluate_combination(const std::string& expression, const std::string& including_file,
                                            const ConvertOptions& options, Diagnostics& warnings) {
  Result<Profile> profile = profile_for(options);
  if (!profile) return profile.error();
  ConvertOptions operands = options;  // operands are frames, whoever asks for the combination
  operands.render = true;
  operands.frames = true;   // whatever the outputs of the combination read
  operands.curves = false;  // an operand's curves are never read
  operands.facts = false;
  const auto load_file = [&](const std::string& name, int column) -> Result<algebra::Value> {
    const Location where = Location::text("<expression>", 1, column);
    if (including_file.empty()) return load_operand(name, where, false, operands, *profile, warnings);
    Result<std::string> path = resolve_include(name, including_file, operands.includes, where);
    if (!path) return path.error();
    return load_operand(*path, where, true, operands, *profile, warnings);
  };
  return algebra::evaluate(expression, load_file, options.limits.max_frames);
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

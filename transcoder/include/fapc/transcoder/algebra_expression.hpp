// The expression language of `fapc combine` (docs/algebra.md): operands are files, operators are
// the Algebra's. Parsed and evaluated in one pass; syntax errors point at the column.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "fapc/codec/limits.hpp"
#include "fapc/transcoder/algebra.hpp"

namespace fapc::algebra {

// A state (a .xpr file) or an animation (every other input).
struct Value {
  std::optional<FacialState> state;
  Animation animation;
};

// Loads the operand written `name`; `column` (1-based) is where it stands in the expression.
using OperandLoader = std::function<Result<Value>(const std::string& name, int column)>;

// Errors in the expression itself come as "<expression>:1:COL" with the expression as the
// source line, so a caret can be drawn. An operator whose result would span more than
// `max_frames` frames (a long delay, a high frame rate) is a limit_exceeded error at its column,
// raised before the frames are allocated.
Result<Value> evaluate(std::string_view expression, const OperandLoader& load,
                       std::int64_t max_frames = Limits{}.max_frames);

}  // namespace fapc::algebra

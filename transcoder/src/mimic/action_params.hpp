// Private: the parameters of one Mimic action, checked (no repeats, no conflicts) and typed.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/timeline/timeline.hpp"
#include "mimic_ast.hpp"

namespace fapc::mimic {

struct ActionParams {
  std::optional<Number> left, right;  // present: given (value 0 when written without one)
  std::optional<Number> in, hold, out, value;
  std::optional<Number> duration, freq, period, min, max;
  std::optional<Param> connect;           // with an optional explicit end value
  std::optional<Param> function;          // linear | sin | log | exp
  std::optional<Param> blend;             // add | average | overwrite
  const Param* first_fade = nullptr;      // in/hold/out/value/connect, for "mixed kinds" errors
  const Param* first_periodic = nullptr;  // duration/freq/period/min/max

  Interpolation interpolation() const;
  std::optional<BlendMode> blend_mode() const;
};

// `error(code, position, message)` builds the diagnostic (the caller knows the file and source).
using ErrorAt = std::function<Diagnostic(ErrorCode, Position, const std::string&)>;
Result<ActionParams> read_params(const std::vector<Param>& params, const ErrorAt& error);

}  // namespace fapc::mimic

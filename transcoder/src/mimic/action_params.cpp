#include "action_params.hpp"

namespace fapc::mimic {
namespace {

bool is_fade_param(const std::string& n) {
  return n == "in" || n == "hold" || n == "out" || n == "value" || n == "connect";
}
bool is_periodic_param(const std::string& n) {
  return n == "duration" || n == "freq" || n == "period" || n == "min" || n == "max";
}
bool is_length(const std::string& n) {
  return n == "in" || n == "hold" || n == "out" || n == "duration" || n == "freq" || n == "period";
}

}  // namespace

Interpolation ActionParams::interpolation() const {
  if (!function) return Interpolation::linear;
  if (function->name == "sin") return Interpolation::sin;
  if (function->name == "log") return Interpolation::log;
  if (function->name == "exp") return Interpolation::exp;
  return Interpolation::linear;
}

std::optional<BlendMode> ActionParams::blend_mode() const {
  if (!blend) return std::nullopt;
  if (blend->name == "average") return BlendMode::average;
  if (blend->name == "overwrite") return BlendMode::overwrite;
  return BlendMode::add;
}

Result<ActionParams> read_params(const std::vector<Param>& params, const ErrorAt& error) {
  ActionParams out;
  for (const Param& p : params) {
    const std::string& n = p.name;
    std::optional<Number>* number = n == "left"       ? &out.left
                                    : n == "right"    ? &out.right
                                    : n == "in"       ? &out.in
                                    : n == "hold"     ? &out.hold
                                    : n == "out"      ? &out.out
                                    : n == "value"    ? &out.value
                                    : n == "duration" ? &out.duration
                                    : n == "freq"     ? &out.freq
                                    : n == "period"   ? &out.period
                                    : n == "min"      ? &out.min
                                    : n == "max"      ? &out.max
                                                      : nullptr;
    if (number) {
      if (*number) return error(p.at, "'" + n + "' is given twice");
      *number = p.value.value_or(Number{0, p.at});
    } else if (n == "connect") {
      if (out.connect) return error(p.at, "'connect' is given twice");
      out.connect = p;
    } else {
      const bool function = n == "linear" || n == "sin" || n == "log" || n == "exp";
      std::optional<Param>& slot = function ? out.function : out.blend;
      if (slot) {
        return error(p.at, "'" + n + "' conflicts with '" + slot->name + "': one " +
                               (function ? "fading function" : "blend mode") + " per action");
      }
      slot = p;
    }
    if (is_fade_param(n) && !out.first_fade) out.first_fade = &p;
    if (is_periodic_param(n) && !out.first_periodic) out.first_periodic = &p;
    if ((n == "left" && out.right) || (n == "right" && out.left)) {
      return error(p.at, "'left' and 'right' together: an action is aligned one way");
    }
    if (p.value && is_length(n) && p.value->value < 0) {
      return error(p.value->at, "'" + n + "' must not be negative");
    }
    if (p.value && (n == "freq" || n == "period") && p.value->value == 0) {
      return error(p.value->at, "'" + n + "' must be greater than 0");
    }
  }
  return out;
}

}  // namespace fapc::mimic

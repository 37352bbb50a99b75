#include "action_params.hpp"

#include <array>

#include "fapc/transcoder/codes.hpp"

namespace fapc::mimic {
namespace {

using N = ParamName;

// In ParamName's order.
constexpr std::array<std::string_view, 19> kNames = {
    "left", "right", "connect", "in",  "hold", "out", "value",   "duration", "freq",     "period",
    "min",  "max",   "linear",  "sin", "log",  "exp", "average", "add",      "overwrite"};

bool is_fade_param(N n) { return n == N::in || n == N::hold || n == N::out || n == N::value || n == N::connect; }
bool is_periodic_param(N n) { return n == N::duration || n == N::freq || n == N::period || n == N::min || n == N::max; }
bool is_length(N n) {
  return n == N::in || n == N::hold || n == N::out || n == N::duration || n == N::freq || n == N::period;
}
bool is_function(N n) { return n == N::linear || n == N::sin || n == N::log || n == N::exp; }

}  // namespace

std::string_view to_string(ParamName name) { return kNames[static_cast<std::size_t>(name)]; }

std::optional<ParamName> param_name(std::string_view text) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == text) return static_cast<ParamName>(i);
  }
  return std::nullopt;
}

Interpolation ActionParams::interpolation() const {
  if (!function) return Interpolation::linear;
  switch (function->id) {
    case N::sin:
      return Interpolation::sin;
    case N::log:
      return Interpolation::log;
    case N::exp:
      return Interpolation::exp;
    default:
      return Interpolation::linear;
  }
}

std::optional<BlendMode> ActionParams::blend_mode() const {
  if (!blend) return std::nullopt;
  if (blend->id == N::average) return BlendMode::average;
  if (blend->id == N::overwrite) return BlendMode::overwrite;
  return BlendMode::add;
}

// The slot of a parameter that carries a number, or nullptr.
static std::optional<Number>* number_slot(ActionParams& out, N n) {
  switch (n) {
    case N::left:
      return &out.left;
    case N::right:
      return &out.right;
    case N::in:
      return &out.in;
    case N::hold:
      return &out.hold;
    case N::out:
      return &out.out;
    case N::value:
      return &out.value;
    case N::duration:
      return &out.duration;
    case N::freq:
      return &out.freq;
    case N::period:
      return &out.period;
    case N::min:
      return &out.min;
    case N::max:
      return &out.max;
    default:
      return nullptr;
  }
}

Result<ActionParams> read_params(const std::vector<Param>& params, const ErrorAt& error) {
  ActionParams out;
  for (const Param& p : params) {
    const N n = p.id;
    if (std::optional<Number>* number = number_slot(out, n)) {
      if (*number) return error(codes::mimic::parameter_twice, p.at, "'" + p.name() + "' is given twice");
      *number = p.value.value_or(Number{0, p.at});
    } else if (n == N::connect) {
      if (out.connect) return error(codes::mimic::parameter_twice, p.at, "'connect' is given twice");
      out.connect = p;
    } else {
      const bool function = is_function(n);
      std::optional<Param>& slot = function ? out.function : out.blend;
      if (slot) {
        return error(codes::mimic::parameter_conflict, p.at,
                     "'" + p.name() + "' conflicts with '" + slot->name() + "': one " +
                         (function ? "fading function" : "blend mode") + " per action");
      }
      slot = p;
    }
    if (is_fade_param(n) && !out.first_fade) out.first_fade = &p;
    if (is_periodic_param(n) && !out.first_periodic) out.first_periodic = &p;
    if ((n == N::left && out.right) || (n == N::right && out.left)) {
      return error(codes::mimic::parameter_conflict, p.at, "'left' and 'right' together: an action is aligned one way");
    }
    if (p.value && is_length(n) && p.value->value < 0) {
      return error(codes::mimic::parameter_out_of_range, p.value->at, "'" + p.name() + "' must not be negative");
    }
    if (p.value && (n == N::freq || n == N::period) && p.value->value == 0) {
      return error(codes::mimic::parameter_out_of_range, p.value->at, "'" + p.name() + "' must be greater than 0");
    }
  }
  return out;
}

}  // namespace fapc::mimic

// The operators on facial states (docs/algebra.md, "Operators"; Algebra definitions 1 to 3).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fapc/codec/fap_table.hpp"
#include "fapc/transcoder/algebra.hpp"
#include "fapc/transcoder/codes.hpp"

namespace fapc::algebra {

std::int32_t round_half_away(double x) {
  // std::round rounds halves away from zero; the clamp keeps absurd weights defined.
  const double r = std::round(x);
  if (r > 2147483647.0) return 2147483647;
  if (r < -2147483648.0) return -2147483647 - 1;
  return static_cast<std::int32_t>(r);
}

FacialState sum(const FacialState& s, const FacialState& t, double v) {
  FacialState out;
  for (std::size_t i = 0; i < out.values.size(); ++i) {
    // Each half is clamped to 32 bits; their sum may not fit (1e300 * X + 1e300 * X), so it is
    // added in 64 bits and clamped again.
    const std::int64_t total = std::int64_t{round_half_away(s.values[i] * v)} + round_half_away(t.values[i] * (1 - v));
    out.values[i] = static_cast<std::int32_t>(std::clamp<std::int64_t>(total, INT32_MIN, INT32_MAX));
  }
  return out;
}

FacialState amplify(const FacialState& s, double w) {
  FacialState out;
  for (std::size_t i = 0; i < out.values.size(); ++i) out.values[i] = round_half_away(w * s.values[i]);
  return out;
}

Mask Mask::all() {
  Mask m;
  m.bits.set();
  return m;
}

Layer Layer::of(const FacialState& s, const Mask& mask, int priority) {
  Layer layer;
  for (int fap = 3; fap <= kFapCount; ++fap) {
    if (mask.covers(fap)) layer.state.at(fap) = s.at(fap);
  }
  layer.priority.fill(priority);
  return layer;
}

Result<Layer> overlap(const Layer& a, const Layer& b) {
  Layer out;
  for (std::size_t i = 0; i < out.state.values.size(); ++i) {
    const std::int32_t s = a.state.values[i];
    const std::int32_t t = b.state.values[i];
    if (s == 0 || t == 0) {
      out.state.values[i] = s + t;
      out.priority[i] = s != 0 ? a.priority[i] : b.priority[i];
    } else if (a.priority[i] == b.priority[i]) {
      return make_error(codes::algebra::equal_priorities, Location{},
                        "equal priorities (" + std::to_string(a.priority[i]) + ") overlap on " +
                            std::string(find_fap(static_cast<int>(i) + 3)->name) +
                            ": give the operands different priorities");
    } else {
      const bool first = a.priority[i] > b.priority[i];
      out.state.values[i] = first ? s : t;
      out.priority[i] = first ? a.priority[i] : b.priority[i];
    }
  }
  return out;
}

Result<FacialState> state_from_entries(const std::vector<ExpressionEntry>& entries, const Profile& profile) {
  std::array<double, kStateSize> sums{};
  for (const ExpressionEntry& entry : entries) {
    const std::vector<FapContribution> drives = resolve_target(entry.parameter, profile);
    if (drives.empty())
      return make_error(codes::profile::unknown_parameter, entry.where,
                        unknown_parameter_message(entry.parameter, profile));
    for (const FapContribution& c : drives) {
      if (c.fap < 3) {
        return make_error(
            codes::algebra::not_a_state_fap, entry.where,
            "'" + entry.parameter + "' is FAP " + std::to_string(c.fap) + "; a facial state holds FAPs 3 to 68");
      }
      sums[static_cast<std::size_t>(c.fap - 3)] += entry.value * c.scale;
    }
  }
  FacialState state;
  for (std::size_t i = 0; i < sums.size(); ++i) state.values[i] = round_half_away(sums[i]);
  return state;
}

}  // namespace fapc::algebra

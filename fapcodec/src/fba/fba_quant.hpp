// Quantisation of FAP values (docs/fba-bitstream.md section 7): rounding half away from zero,
// except that |v| equal to half an even step goes to 0. A step of 0 means no quantisation. Private
// to fapcodec.
#pragma once

#include <cstdint>
#include <cstdlib>

#include "fba/fba_syntax.hpp"

namespace fapc::fba {

inline std::int64_t quantise(std::int64_t v, std::int64_t step) {
  if (step == 0) return v;
  const std::int64_t a = v < 0 ? -v : v;
  const std::int64_t h = step / 2;
  const std::int64_t level = a <= h ? 0 : (a + h) / step;
  return v < 0 ? -level : level;
}

inline std::int64_t dequantise(std::int64_t q, std::int64_t step) { return step == 0 ? q : q * step; }

// The largest level whose reconstruction stays within +-`legal` (a FAP's legal range, or 63 for
// a blend or intensity): players clamp what lies beyond, each in its own way, so a value inside
// its range must never be reconstructed outside it (docs/fba.md 2, "Legal ranges").
inline std::int64_t largest_legal_level(std::int64_t legal, std::int64_t step) {
  return step == 0 ? legal : legal / step;
}

// The value a reconstruction should be within half a step of: the value itself, or the largest
// legal reconstruction when the value lies between that and the end of its legal range.
inline std::int64_t legal_target(std::int64_t value, std::int64_t legal, std::int64_t step) {
  const std::int64_t top = dequantise(largest_legal_level(legal, step), step);
  if (value > top && value <= legal) return top;
  if (value < -top && value >= -legal) return -top;
  return value;
}

// The smallest 5-bit range value v whose range (v * 60) / scaler covers `magnitude` quantised
// units (docs/fba-bitstream.md section 5.6); above kMaxRangeValue when nothing can.
inline int range_value_for(std::int64_t magnitude, int scaler) {
  return static_cast<int>((magnitude * scaler + kRangeDelta - 1) / kRangeDelta);
}

}  // namespace fapc::fba

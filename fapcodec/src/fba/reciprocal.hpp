// Division by a model total without a divide instruction. The coder divides by the total of a
// model twice per symbol (docs/fba-bitstream.md sections 6.3, 6.5), on the chain of operations each
// symbol waits for; a multiplication and a shift by a precomputed reciprocal give exactly the
// same quotient for every numerator the coder can produce (Granlund and Montgomery, 1994: with
// l = ceil(log2 d) and m = floor(2^(30+l) / d) + 1, floor(n m / 2^(30+l)) = floor(n / d) for all
// 0 <= n < 2^30, because 2^(30+l) < m d <= 2^(30+l) + 2^l). Private to fapcodec.
#pragma once

#include <array>
#include <cstdint>

#include "fba/adaptive_model.hpp"

namespace fapc::fba {

struct Reciprocal {
  std::uint32_t multiplier = 0;
  std::uint32_t shift = 0;
};

// For every divisor 1..kMaxFrequency (index 0 unused).
extern const std::array<Reciprocal, kMaxFrequency + 1> kReciprocals;

// floor(n / d) for 0 <= n < 2^30 and 1 <= d <= kMaxFrequency. The coder's numerators are an
// interval length (at most 65536) times a count (at most the total, 16383): below 2^30.
inline std::int32_t divide_by_total(std::int32_t n, std::int32_t d) {
  const Reciprocal& r = kReciprocals[static_cast<std::size_t>(d)];
  return static_cast<std::int32_t>((static_cast<std::uint64_t>(n) * r.multiplier) >> r.shift);
}

}  // namespace fapc::fba

#include "fba/reciprocal.hpp"

#include <bit>

namespace fapc::fba {

namespace {

constexpr std::array<Reciprocal, kMaxFrequency + 1> make_reciprocals() {
  std::array<Reciprocal, kMaxFrequency + 1> table{};
  for (std::uint32_t d = 1; d <= static_cast<std::uint32_t>(kMaxFrequency); ++d) {
    const auto l = static_cast<std::uint32_t>(std::bit_width(d - 1));  // ceil(log2 d)
    const std::uint32_t shift = 30 + l;
    table[d] = {static_cast<std::uint32_t>((std::uint64_t{1} << shift) / d + 1), shift};
  }
  return table;
}

}  // namespace

constexpr std::array<Reciprocal, kMaxFrequency + 1> kReciprocals = make_reciprocals();

}  // namespace fapc::fba

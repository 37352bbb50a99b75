#include "fapc/xml/text.hpp"

#include <charconv>
#include <cmath>

namespace fapc::xml {

std::optional<double> decimal(std::string_view s) {
  double value = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || error != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace fapc::xml

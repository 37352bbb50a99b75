// SMIL 2.0 clock values (Timing module, "Clock values"):
//   Full-clock-value    ::= Hours ":" Minutes ":" Seconds ("." Fraction)?
//   Partial-clock-value ::= Minutes ":" Seconds ("." Fraction)?
//   Timecount-value     ::= Timecount ("." Fraction)? ("h" | "min" | "s" | "ms")?
// Minutes and Seconds are two digits, 00..59; a timecount without a metric is seconds.
#include <charconv>
#include <cmath>
#include <string>

#include "fapc/xml/clock_value.hpp"

namespace fapc::xml {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\n' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// DIGIT+ ("." DIGIT+)?, the whole of `s`.
std::optional<double> decimal(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && is_digit(s[i])) ++i;
  if (i == 0) return std::nullopt;
  if (i < s.size()) {
    if (s[i] != '.' || i + 1 == s.size()) return std::nullopt;
    for (std::size_t k = i + 1; k < s.size(); ++k)
      if (!is_digit(s[k])) return std::nullopt;
  }
  double value = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (error != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// Two digits 00..59.
std::optional<double> sixty(std::string_view s) {
  if (s.size() != 2 || !is_digit(s[0]) || !is_digit(s[1]) || s[0] > '5') return std::nullopt;
  return (s[0] - '0') * 10 + (s[1] - '0');
}

std::optional<double> clock(std::string_view s) {
  const std::size_t first = s.find(':');
  const std::size_t second = first == std::string_view::npos ? first : s.find(':', first + 1);
  std::string_view hours, minutes, seconds;
  if (second != std::string_view::npos) {
    hours = s.substr(0, first);
    minutes = s.substr(first + 1, second - first - 1);
    seconds = s.substr(second + 1);
  } else {
    minutes = s.substr(0, first);
    seconds = s.substr(first + 1);
  }
  double h = 0;
  if (second != std::string_view::npos) {
    const auto parsed = decimal(hours);
    if (!parsed || hours.find('.') != std::string_view::npos) return std::nullopt;
    h = *parsed;
  }
  const auto m = sixty(minutes);
  const std::size_t dot = seconds.find('.');
  const auto whole = sixty(seconds.substr(0, dot));
  if (!m || !whole) return std::nullopt;
  double fraction = 0;
  if (dot != std::string_view::npos) {
    const auto parsed = decimal("0" + std::string(seconds.substr(dot)));
    if (!parsed) return std::nullopt;
    fraction = *parsed;
  }
  return h * 3600 + *m * 60 + *whole + fraction;
}

std::optional<double> timecount(std::string_view s) {
  double scale = 1;
  if (s.ends_with("ms")) {
    scale = 0.001;
    s.remove_suffix(2);
  } else if (s.ends_with("min")) {
    scale = 60;
    s.remove_suffix(3);
  } else if (s.ends_with("h")) {
    scale = 3600;
    s.remove_suffix(1);
  } else if (s.ends_with("s")) {
    s.remove_suffix(1);
  }
  const auto value = decimal(s);
  if (!value) return std::nullopt;
  const double seconds = *value * scale;
  if (!std::isfinite(seconds)) return std::nullopt;
  return seconds;
}

}  // namespace

std::optional<double> parse_clock_value(std::string_view text) {
  const std::string_view s = trim(text);
  if (s.empty()) return std::nullopt;
  return s.find(':') != std::string_view::npos ? clock(s) : timecount(s);
}

}  // namespace fapc::xml

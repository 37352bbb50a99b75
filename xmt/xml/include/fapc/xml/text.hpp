// Attribute and field text as the XML readers take it: blanks around a value do not count, and a
// number is a whole decimal, finite.
#pragma once

#include <cctype>
#include <optional>
#include <string_view>

namespace fapc::xml {

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// The number the whole of `s` spells; empty for anything else (blanks, a sign other than '-',
// trailing text, inf, nan).
std::optional<double> decimal(std::string_view s);

}  // namespace fapc::xml

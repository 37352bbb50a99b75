// The words and numbers FML values are written in: trimmed text, decimals, expression and axis names.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>

#include "fml/fml_words.hpp"

#include "fapc/xml/text.hpp"

namespace fapc::fml::reading {

std::string trim(std::string_view s) { return std::string(xml::trim(s)); }

std::optional<double> number(std::string_view text) { return xml::decimal(xml::trim(text)); }

std::string format_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

bool same_value(const std::string& a, const std::string& b) {
  const auto x = number(a), y = number(b);
  return x && y ? *x == *y : trim(a) == trim(b);
}

std::optional<int> expression_number(const std::string& type) {
  static const std::map<std::string, int> kWords = {{"smile", 1},    {"joy", 1},       {"happy", 1},   {"happiness", 1},
                                                    {"sadness", 2},  {"sad", 2},       {"anger", 3},   {"angry", 3},
                                                    {"fear", 4},     {"afraid", 4},    {"disgust", 5}, {"disgusted", 5},
                                                    {"surprise", 6}, {"surprised", 6}, {"normal", 0},  {"neutral", 0}};
  if (const auto n = number(type)) {
    if (*n == std::floor(*n) && *n >= 0 && *n <= 6) return static_cast<int>(*n);
    return std::nullopt;
  }
  const auto found = kWords.find(lower(trim(type)));
  if (found == kWords.end()) return std::nullopt;
  return found->second;
}

std::optional<int> head_axis(const std::string& type) {
  const std::string t = lower(trim(type));
  if (t == "0" || t == "yaw") return 0;
  if (t == "1" || t == "pitch") return 1;
  if (t == "2" || t == "roll") return 2;
  return std::nullopt;
}

// The head's allowed range per axis, in degrees, from the model's range items.

}  // namespace fapc::fml::reading

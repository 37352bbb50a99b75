#include "xmto/animation_function.hpp"
#include "fapc/xml/text.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "fapc/xmto/codes.hpp"

namespace fapc::xmto {
namespace {

// SMIL values may carry a '+' sign.
std::optional<double> number(std::string_view s) {
  s = xml::trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  return xml::decimal(s);
}

// "a; b; c" (a trailing ';' allowed, as SVG writers produce it). Empty on a bad item.
std::optional<std::vector<double>> number_list(std::string_view text) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t stop = text.find(';', start);
    if (stop == std::string_view::npos) stop = text.size();
    const std::string_view item = xml::trim(text.substr(start, stop - start));
    const bool last = stop == text.size();
    if (!(item.empty() && last && !out.empty())) {
      const auto value = number(item);
      if (!value) return std::nullopt;
      out.push_back(*value);
    }
    start = stop + 1;
  }
  return out;
}

class Reader {
 public:
  Reader(const xml::XmlDocument& doc, const xmlNode* element) : doc_(doc), element_(element) {}
  std::optional<Diagnostic> error;

  std::optional<double> value(const char* name) {
    const auto text = xml::attribute(element_, name);
    if (!text || error) return std::nullopt;
    if (const auto parsed = number(*text)) return parsed;
    fail(codes::xmto::not_a_number, name, std::string(name) + " '" + *text + "' is not a number");
    return std::nullopt;
  }

  std::optional<std::vector<double>> list(const char* name, const char* what) {
    const auto text = xml::attribute(element_, name);
    if (!text || error) return std::nullopt;
    if (auto parsed = number_list(*text)) return parsed;
    fail(codes::xmto::bad_list, name, std::string(name) + " '" + *text + "': expected " + what + " separated by ';'");
    return std::nullopt;
  }

  // One of `allowed` (the first is the default when the attribute is absent).
  std::string keyword(const char* name, std::initializer_list<const char*> allowed) {
    const auto text = xml::attribute(element_, name);
    if (!text || error) return *allowed.begin();
    const std::string_view s = xml::trim(*text);
    for (const char* word : allowed)
      if (s == word) return word;
    std::string expected;
    std::size_t i = 0;
    for (const char* word : allowed) {
      expected += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + std::string(word);
      ++i;
    }
    fail(codes::xmto::unsupported_keyword, name,
         std::string(name) + " '" + *text + "' is not supported: expected " + expected);
    return *allowed.begin();
  }

  void fail(ErrorCode code, const char* attribute, std::string message) {
    if (!error) error = doc_.error(code, element_, attribute, std::move(message));
  }

  Diagnostic warning(const char* attribute, std::string message) const {
    return doc_.warning(element_, attribute, std::move(message));
  }

 private:
  const xml::XmlDocument& doc_;
  const xmlNode* element_;
};

bool has(const xmlNode* element, const char* name) { return xml::attribute(element, name).has_value(); }

// keyTimes rules of SMIL: one per value, 0 <= t <= 1, non-decreasing, first 0, last 1 unless
// discrete.
void check_key_times(Reader& reader, const AnimationFunction& f) {
  const std::vector<double>& times = f.key_times;
  if (times.size() != f.values.size()) {
    reader.fail(
        codes::xmto::bad_key_times, "keyTimes",
        "keyTimes has " + std::to_string(times.size()) + " times for " + std::to_string(f.values.size()) + " values");
    return;
  }
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] < 0 || times[i] > 1 || (i > 0 && times[i] < times[i - 1])) {
      reader.fail(codes::xmto::bad_key_times, "keyTimes", "keyTimes must rise from 0 to 1 (fractions of dur)");
      return;
    }
  }
  if (times.front() != 0) reader.fail(codes::xmto::bad_key_times, "keyTimes", "keyTimes must begin with 0");
  if (f.calc == CalcMode::linear && times.back() != 1)
    reader.fail(codes::xmto::bad_key_times, "keyTimes", "keyTimes must end with 1 unless calcMode is discrete");
}

}  // namespace

Result<AnimationFunction> read_animate(const xml::XmlDocument& doc, const xmlNode* element, std::optional<double> dur,
                                       Diagnostics& warnings) {
  Reader reader(doc, element);
  AnimationFunction f;
  f.simple_duration = dur;
  const std::string calc = reader.keyword("calcMode", {"linear", "discrete", "paced"});
  f.calc = calc == "discrete" ? CalcMode::discrete : calc == "paced" ? CalcMode::paced : CalcMode::linear;
  const bool sum = reader.keyword("additive", {"replace", "sum"}) == "sum";
  f.accumulate = reader.keyword("accumulate", {"none", "sum"}) == "sum";
  f.blend = sum ? BlendMode::add : BlendMode::overwrite;
  const auto values = reader.list("values", "numbers");
  const auto from = reader.value("from");
  const auto to = reader.value("to");
  const auto by = reader.value("by");
  if (reader.error) return *reader.error;

  if (values) {
    f.values = *values;
    for (const char* ignored : {"from", "to", "by"})
      if (has(element, ignored))
        warnings.push_back(reader.warning(ignored, std::string(ignored) + " is ignored: values is given"));
  } else if (to) {
    if (by) warnings.push_back(reader.warning("by", "by is ignored: to is given"));
    f.values = {from.value_or(0), *to};
    if (!from) {
      // A to-animation starts from whatever the attribute is when it begins and replaces it.
      f.to_animation = true;
      if (sum) warnings.push_back(reader.warning("additive", "additive is ignored: a to animation replaces"));
      if (f.accumulate)
        warnings.push_back(reader.warning("accumulate", "accumulate is ignored: a to animation does not accumulate"));
      f.blend = BlendMode::overwrite;
      f.accumulate = false;
    }
  } else if (by) {
    f.values = {from.value_or(0), from.value_or(0) + *by};
    if (!from) {
      // A by-animation adds its change to the attribute (SMIL), whatever additive says.
      if (has(element, "additive") && !sum)
        warnings.push_back(reader.warning("additive", "additive is ignored: a by animation adds"));
      f.blend = BlendMode::add;
    }
  } else {
    return doc.error(codes::xmto::animates_nothing, element, from ? "from" : "attributeName",
                     "animate needs values, to or by (from alone animates nothing)");
  }
  if (f.values.empty()) return doc.error(codes::xmto::animates_nothing, element, "values", "values is empty");

  if (const auto key_times = reader.list("keyTimes", "fractions")) {
    if (f.calc == CalcMode::paced) {
      warnings.push_back(reader.warning("keyTimes", "keyTimes is ignored with calcMode paced"));
    } else {
      f.key_times = *key_times;
      check_key_times(reader, f);
    }
  }
  if (reader.error) return *reader.error;
  return f;
}

Result<AnimationFunction> read_set(const xml::XmlDocument& doc, const xmlNode* element, std::optional<double> dur) {
  Reader reader(doc, element);
  const auto to = reader.value("to");
  if (reader.error) return *reader.error;
  if (!to) return doc.error(codes::xmto::animates_nothing, element, "set needs a to value");
  AnimationFunction f;
  f.values = {*to};
  f.calc = CalcMode::discrete;
  f.simple_duration = dur;
  return f;
}

Curve animation_curve(const AnimationShape& shape, std::span<const double> values, std::span<const double> key_times,
                      double underlying, int iteration) {
  std::vector<double> v(values.begin(), values.end());
  if (shape.to_animation) v.front() = underlying;
  const double shift = shape.accumulate ? iteration * v.back() : 0;
  const std::size_t n = v.size();
  if (!shape.simple_duration || n == 1) return Curve::constant(v.front() + shift);
  const double d = *shape.simple_duration;
  const CalcMode calc = shape.calc;

  // Where each value sits, as a fraction of the simple duration.
  std::vector<double> at(n);
  if (!key_times.empty()) {
    at.assign(key_times.begin(), key_times.end());
  } else if (calc == CalcMode::discrete) {
    for (std::size_t i = 0; i < n; ++i) at[i] = static_cast<double>(i) / static_cast<double>(n);
  } else {
    double total = 0;
    if (calc == CalcMode::paced)
      for (std::size_t i = 1; i < n; ++i) total += std::abs(v[i] - v[i - 1]);
    double walked = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0 && total > 0) walked += std::abs(v[i] - v[i - 1]);
      // paced: distance walked so far; linear (or paced over no distance): equal segments.
      at[i] = total > 0 ? walked / total : static_cast<double>(i) / static_cast<double>(n - 1);
    }
  }
  const Interpolation how = calc == CalcMode::discrete ? Interpolation::step : Interpolation::linear;
  Curve curve;
  curve.keys.reserve(n);
  for (std::size_t i = 0; i < n; ++i) curve.keys.push_back(KeyPoint{at[i] * d, v[i] + shift, how});
  return curve;
}

}  // namespace fapc::xmto

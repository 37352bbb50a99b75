// The repeat attribute of any element of the story, read into its Timing.
#include <algorithm>

#include "fml/fml_reader.hpp"

namespace fapc::fml::reading {

// repeat: a count, "indefinite", an event (loop until it is set: its value is the count, 0
// meaning once, unset meaning indefinitely) or "event;value" (loop until it has that value).
bool FmlReader::apply_repeat(const xmlNode* node, const std::optional<std::string>& repeat, Timing& timing) {
  if (!repeat) return true;
  const std::string text = trim(*repeat);
  if (text == "indefinite") {
    timing.repeat_indefinite = true;
    return true;
  }
  if (const auto n = number(text)) {
    if (*n <= 0) {
      fail(doc_.error(codes::fml::bad_repeat, node, "repeat", "repeat must be a count above 0"));
      return false;
    }
    if (*n > static_cast<double>(options_.limits.max_runs)) {
      fail(limit_at(doc_.error(codes::limit::runs, node, "repeat", ""),
                    "repeat " + text + " asks for more runs than allowed"));
      return false;
    }
    timing.repeat = *n;
    return true;
  }
  const std::size_t semicolon = text.find(';');
  const std::string event = trim(text.substr(0, semicolon));
  if (!events_.count(event)) {
    fail(doc_.error(codes::fml::bad_repeat, node, "repeat",
                    "repeat '" + text + "' is not a count, indefinite, or an event declared in the model"));
    return false;
  }
  const auto value = event_value(event);
  if (semicolon != std::string::npos) {
    const std::string until = trim(text.substr(semicolon + 1));
    timing.repeat_indefinite = !(value && same_value(*value, until));
  } else if (!value) {
    timing.repeat_indefinite = true;
  } else {
    const auto count = number(*value);
    timing.repeat = count && *count >= 1 ? std::min(*count, static_cast<double>(options_.limits.max_runs) + 1) : 1;
  }
  return true;
}

}  // namespace fapc::fml::reading

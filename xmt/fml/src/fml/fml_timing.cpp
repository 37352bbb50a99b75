#include "fml/fml_timing.hpp"

#include "fapc/xml/clock_value.hpp"

namespace fapc::xmt {

Result<FmlTiming> read_fml_timing(const xml::XmlDocument& doc, const xmlNode* element) {
  FmlTiming timing;
  const auto read = [&](const char* name, std::optional<double>& out) -> Status {
    const auto text = xml::attribute(element, name);
    if (!text) return ok_status();
    out = parse_clock_value(*text);
    if (!out) {
      return doc.error(element, name, std::string(name) + " '" + *text +
                                          "' is not a time (seconds: 3, 3s, 250ms, 1.5min, 00:01.5)");
    }
    return ok_status();
  };
  const char* duration_name = xml::attribute(element, "duration") ? "duration" : "dur";
  for (const auto& [name, field] : {std::pair<const char*, std::optional<double>*>{"begin", &timing.begin},
                                    {duration_name, &timing.duration},
                                    {"end", &timing.end}}) {
    if (Status s = read(name, *field); !s) return s.error();
  }
  if (timing.duration && *timing.duration < 0) {
    return doc.error(element, duration_name, std::string(duration_name) + " cannot be negative");
  }
  if (timing.end && *timing.end <= timing.begin.value_or(0)) {
    return doc.error(element, "end", "end must come after begin (both count from the same point)");
  }
  timing.repeat = xml::attribute(element, "repeat");
  return timing;
}

Timing group_timing(const FmlTiming& timing) {
  Timing out;
  out.offset = timing.begin.value_or(0);
  out.duration = timing.duration;
  out.end = timing.end;
  return out;
}

Timing move_timing(const FmlTiming& timing, double intrinsic) {
  Timing out;
  out.offset = timing.begin.value_or(0);
  out.duration = timing.end ? *timing.end - out.offset : timing.duration.value_or(intrinsic);
  return out;
}

}  // namespace fapc::xmt

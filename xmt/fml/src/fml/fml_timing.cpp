#include "fml/fml_timing.hpp"

#include <algorithm>

#include "fapc/fml/codes.hpp"
#include "fapc/xml/clock_value.hpp"

namespace fapc::fml {

Result<FmlTiming> read_fml_timing(const xml::XmlDocument& doc, const xmlNode* element) {
  FmlTiming timing;
  const auto read = [&](const char* name, std::optional<double>& out) -> Status {
    const auto text = xml::attribute(element, name);
    if (!text) return ok_status();
    out = xml::parse_clock_value(*text);
    if (!out) {
      return doc.error(codes::fml::bad_time, element, name,
                       std::string(name) + " '" + *text + "' is not a time (seconds: 3, 3s, 250ms, 1.5min, 00:01.5)");
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
    return doc.error(codes::fml::bad_time, element, duration_name, std::string(duration_name) + " cannot be negative");
  }
  if (timing.end && *timing.end <= timing.begin.value_or(0)) {
    return doc.error(codes::fml::bad_time, element, "end",
                     "end must come after begin (both count from the same point)");
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

double estimated_runs(const ScheduleNode& node, double available, double& shortest,
                      const std::function<double(std::size_t leaf_id)>& leaf_runs) {
  const Timing& t = node.timing;
  double own = 0;
  double children_runs = 0;
  if (node.kind == ScheduleNode::Kind::leaf) {
    own = t.duration.value_or(0);
    children_runs = leaf_runs(node.leaf_id);
  } else {
    const double inner = t.duration.value_or(available);
    for (const ScheduleNode& child : node.children) {
      double child_shortest = 0;
      children_runs += estimated_runs(child, inner, child_shortest, leaf_runs);
      const double reach = child.timing.offset + child_shortest;
      own = node.kind == ScheduleNode::Kind::sequence ? own + reach : std::max(own, reach);
    }
    if (t.duration) own = *t.duration;
  }
  const double repeats = !t.repeat_indefinite ? std::max(t.repeat, 1.0) : own > 0 ? available / own : 1.0;
  shortest = t.end ? std::max(0.0, *t.end - t.offset) : t.repeat_indefinite ? 0 : own * t.repeat;
  return children_runs * std::max(repeats, 1.0);
}

}  // namespace fapc::fml

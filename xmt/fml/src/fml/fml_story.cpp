// The story: its time containers (seq, par, action, excl) as the schedule tree, element by element,
// bounded in depth.
#include <array>

#include "fapc/codec/nesting_limit.hpp"
#include "fml/fml_reader.hpp"

namespace fapc::fml::reading {

ScheduleNode FmlReader::remember(ScheduleNode node, const xmlNode* element) {
  element_names_.push_back(names_.number(xml::local_name(element)));
  node.tag = element_names_.size();
  return node;
}

void FmlReader::read_story(const xmlNode* story) {
  check_given_events();
  check_attributes(story, {});
  tree_.leaves.reserve(doc_.element_count());
  tree_.root = container(story, Kind::sequence, Timing{});
}

// A time container's children in order; excl branches and unknown elements are handled here.
// Streamed, the containers among them are read child by child, and each child of the story is
// freed once read (a template's, which behaviors read again, never).
ScheduleNode FmlReader::container(const xmlNode* node, Kind kind, Timing timing) {
  static constexpr std::array<std::string_view, 4> kContainers{"action", "act", "seq", "par"};
  ScheduleNode group = remember(ScheduleNode::group(kind, timing, doc_.where(node)), node);
  group.children.reserve(doc_.child_count(node));  // no regrowth: a tree is ~all its nodes
  check_text(node);
  for (const xmlNode* child : doc_.children(node, kContainers, expanding_.empty())) {
    if (error_) break;
    if (auto placed = element(child)) group.children.push_back(std::move(*placed));
  }
  return group;
}

std::optional<ScheduleNode> FmlReader::element(const xmlNode* node) {
  if (error_ || !count_node(node)) return std::nullopt;
  if (depth_ >= kMaxNestingDepth) {
    Diagnostic deep = nesting_too_deep(doc_.where(node), "elements (with templates expanded)");
    deep.source_line = doc_.line_text(deep.where.line);
    fail(std::move(deep));
    return std::nullopt;
  }
  ++depth_;
  std::optional<ScheduleNode> read = element_at_depth(node);
  --depth_;
  return read;
}

std::optional<ScheduleNode> FmlReader::element_at_depth(const xmlNode* node) {
  const std::string_view name = xml::local_name(node);
  Result<FmlTiming> timing = read_fml_timing(doc_, node);
  if (!timing) {
    fail(timing.error());
    return std::nullopt;
  }
  const bool group =
      name == "action" || name == "act" || name == "seq" || name == "par" || name == "excl" || name == "behavior";
  const bool move =
      name == "talk" || name == "expr" || name == "hdmv" || name == "fap" || name == "param" || name == "wait";
  if (!group && !move) {
    // Extensions of other systems (e.g. <emotion> in the published sample): their FML
    // children still play, together, as in a par.
    unknown(node, "is not part of FML; its children are read as if in a par");
    check_attributes(node, kTiming);
    Timing t = group_timing(*timing);
    if (!apply_repeat(node, timing->repeat, t)) return std::nullopt;
    return container(node, Kind::parallel, t);
  }
  std::optional<ScheduleNode> placed = group ? time_container(node, *timing) : this->move(node, *timing);
  if (!placed || error_) return std::nullopt;
  if (!apply_repeat(node, timing->repeat, placed->timing)) return std::nullopt;
  return placed;
}

std::optional<ScheduleNode> FmlReader::time_container(const xmlNode* node, const FmlTiming& timing) {
  const std::string_view name = xml::local_name(node);
  if (name == "excl") return excl(node, timing);
  if (name == "behavior") return behavior(node, timing);
  check_attributes(node, kTiming, {"ev_val", "event_value"});
  return container(node, name == "par" ? Kind::parallel : Kind::sequence, group_timing(timing));
}

// The branch whose ev_val is the event's value plays, alone; the others are read for errors.
std::optional<ScheduleNode> FmlReader::excl(const xmlNode* node, const FmlTiming& timing) {
  check_attributes(node, kTiming, {"ev_name", "ev_id", "event_name", "ev_val", "event_value"});
  check_text(node);
  const auto event = spelled(node, "ev_name", {"ev_id", "event_name"});
  if (!event) {
    fail(doc_.error(codes::fml::missing_attribute, node, "excl needs ev_name, the event that chooses its branch"));
    return std::nullopt;
  }
  const std::string name = trim(*event);
  if (!events_.count(name) && !options_.events.count(name)) {
    fail(doc_.error(codes::fml::undeclared_event, node, xml::attribute(node, "ev_name") ? "ev_name" : "",
                    "event '" + name + "' is not declared in the model (<event name=\"" + name + "\" val=\"-1\"/>)"));
    return std::nullopt;
  }
  const auto value = event_value(name);
  ScheduleNode group = remember(ScheduleNode::group(Kind::parallel, group_timing(timing), doc_.where(node)), node);
  bool chosen = false;
  for (const xmlNode* child : xml::element_children(node)) {
    const auto branch = spelled(child, "ev_val", {"event_value"});
    if (!branch) {
      result_.warnings.push_back(
          doc_.warning(child, std::string(xml::local_name(child)) + " in excl has no ev_val: it never plays"));
    }
    std::optional<ScheduleNode> placed = element(child);
    if (error_) return std::nullopt;
    if (placed && branch && value && !chosen && same_value(*branch, *value)) {
      group.children.push_back(std::move(*placed));
      chosen = true;
    }
  }
  if (!value) {
    result_.warnings.push_back(doc_.warning(
        node, "event '" + name + "' has no value (give --event " + name + "=VALUE): the excl plays nothing"));
  } else if (!chosen) {
    result_.warnings.push_back(doc_.warning(
        node, "no branch of the excl has ev_val=\"" + *value + "\" (event '" + name + "'): it plays nothing"));
  }
  return group;
}

}  // namespace fapc::fml::reading

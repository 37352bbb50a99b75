// Templates: defined in the model, expanded where a behavior plays them, never into themselves.
#include <algorithm>

#include "fml/fml_reader.hpp"

namespace fapc::fml::reading {

void FmlReader::read_template(const xmlNode* item) {
  const auto name = xml::attribute(item, "name");
  if (!name || trim(*name).empty()) {
    fail(doc_.error(codes::fml::missing_attribute, item, "template needs name"));
  } else if (!templates_.emplace(trim(*name), item).second) {
    fail(doc_.error(codes::fml::declared_twice, item, "name", "template '" + trim(*name) + "' is defined twice"));
  } else {
    result_.templates.push_back(trim(*name));
  }
}

std::optional<ScheduleNode> FmlReader::behavior(const xmlNode* node, const FmlTiming& timing) {
  check_attributes(node, kTiming, {"name", "template", "ev_val", "event_value"});
  check_text(node);
  const auto name = spelled(node, "name", {"template"});
  if (!name) {
    fail(doc_.error(codes::fml::missing_attribute, node, "behavior needs name, the template it plays"));
    return std::nullopt;
  }
  for (const xmlNode* child : xml::element_children(node)) {
    unknown(child, "inside behavior is ignored: a behavior plays its template, which holds the content");
  }
  const std::string t = trim(*name);
  const auto found = templates_.find(t);
  if (found == templates_.end()) {
    std::string known;
    for (const auto& [n, item] : templates_) known += (known.empty() ? "" : ", ") + n;
    fail(doc_.error(codes::fml::unknown_template, node, xml::attribute(node, "name") ? "name" : "template",
                    "no template '" + t + "' in the model" + (known.empty() ? "" : " (templates: " + known + ")")));
    return std::nullopt;
  }
  if (std::find(expanding_.begin(), expanding_.end(), t) != expanding_.end()) {
    std::string chain;
    for (const std::string& e : expanding_) chain += e + " -> ";
    fail(doc_.error(codes::fml::recursive_template, node, "template '" + t + "' uses itself: " + chain + t));
    return std::nullopt;
  }
  expanding_.push_back(t);
  ScheduleNode group = container(found->second, Kind::sequence, group_timing(timing));
  expanding_.pop_back();
  group.source = doc_.where(node);
  return remember(std::move(group), node);
}

}  // namespace fapc::fml::reading

// The model: the character, the head's ranges, the events (and their values for this run),
// the templates' names. Nothing of it animates by itself.
#include "fml/fml_reader.hpp"

namespace fapc::fml::reading {

void FmlReader::read_model(const xmlNode* model) {
  check_attributes(model, {});
  check_text(model);
  for (const xmlNode* item : xml::element_children(model)) {
    const std::string_view name = xml::local_name(item);
    if (name == "character") {
      check_attributes(item, {"name", "lang", "voice"});
      result_.character = xml::attribute(item, "name").value_or("");
      model_language_ = trim(xml::attribute(item, "lang").value_or(""));
      model_voice_ = trim(xml::attribute(item, "voice").value_or(""));
    } else if (name == "img") {
      check_attributes(item, {"src", "type"});  // for the player's face model: no FAPs
    } else if (name == "param") {
      check_attributes(item, {"name", "val"});  // a player parameter (e.g. an FDP): no FAPs
    } else if (name == "range") {
      check_attributes(item, {"type", "val"}, {"dir"});
      read_range(item);
    } else if (name == "event") {
      check_attributes(item, {"name", "val"}, {"id"});
      read_event(item);
    } else if (name == "template") {
      check_attributes(item, {"name"});
      read_template(item);
    } else {
      unknown(item, "is not an FML model item and was skipped");
      continue;
    }
    if (name != "template") check_text(item);
  }
}

void FmlReader::read_range(const xmlNode* item) {
  const auto val_text = xml::attribute(item, "val");
  const auto val = val_text ? number(*val_text) : std::nullopt;
  if (!val || *val < 0) {
    fail(doc_.error(codes::fml::bad_range, item, val_text ? "val" : "",
                    "range needs val, the largest angle in degrees (>= 0)"));
    return;
  }
  // type: a direction (the paper's "left"); dir: an axis, both directions (docs/fml.md,
  // "Spellings").
  if (const auto dir = spelled(item, "type", {"dir"})) {
    const std::string d = lower(trim(*dir));
    const auto axis = head_axis(d);
    // Positive FAP directions (docs/fap-table.md section 2): yaw left, pitch down, roll right.
    if (axis) {
      limits_.min[*axis] = -*val;
      limits_.max[*axis] = *val;
    } else if (d == "left") {
      limits_.max[0] = *val;
    } else if (d == "right") {
      limits_.min[0] = -*val;
    } else if (d == "down") {
      limits_.max[1] = *val;
    } else if (d == "up") {
      limits_.min[1] = -*val;
    } else if (d == "roll-right" || d == "tilt-right") {
      limits_.max[2] = *val;
    } else if (d == "roll-left" || d == "tilt-left") {
      limits_.min[2] = -*val;
    } else {
      fail(doc_.error(codes::fml::bad_range, item, xml::attribute(item, "type") ? "type" : "dir",
                      "range type '" + *dir +
                          "' is not a direction (left, right, up, down, roll-left, "
                          "roll-right) or an axis (0 yaw, 1 pitch, 2 roll)"));
    }
    return;
  }
  fail(doc_.error(codes::fml::bad_range, item,
                  "range needs type, the direction it limits (left, right, up, down, ...)"));
}

void FmlReader::read_event(const xmlNode* item) {
  const auto name = spelled(item, "name", {"id"});
  if (!name || trim(*name).empty()) {
    fail(doc_.error(codes::fml::missing_attribute, item, "event needs name"));
    return;
  }
  if (events_.count(trim(*name))) {
    fail(doc_.error(codes::fml::declared_twice, item, "event '" + trim(*name) + "' is declared twice"));
    return;
  }
  events_[trim(*name)] = EventDeclaration{xml::attribute(item, "val")};
}

// The value an event has for this run: --event wins over the model's val; -1 means unset.
std::optional<std::string> FmlReader::event_value(const std::string& name) const {
  if (const auto given = options_.events.find(name); given != options_.events.end()) return given->second;
  const auto declared = events_.find(name);
  if (declared == events_.end() || !declared->second.value) return std::nullopt;
  if (const auto n = number(*declared->second.value); n && *n < 0) return std::nullopt;
  return declared->second.value;
}

void FmlReader::check_given_events() {
  for (const auto& [name, value] : options_.events) {
    if (!events_.count(name)) {
      result_.warnings.push_back(make_warning(codes::fml::unused_event, Location::whole_file(doc_.file()),
                                              "--event " + name + " is not declared in the model; it is unused"));
    }
  }
  for (const auto& [name, declaration] : events_) result_.events.emplace_back(name, event_value(name).value_or(""));
}

}  // namespace fapc::fml::reading

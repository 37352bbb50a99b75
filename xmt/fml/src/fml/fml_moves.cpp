// The moves that are not speech: wait, expr, hdmv, fap and param, each a leaf of the tree.
#include <algorithm>

#include "fapc/codec/fap_table.hpp"
#include "fml/fml_reader.hpp"

namespace fapc::fml::reading {

namespace {

// FAP angle units are 1e-5 rad.
constexpr double kAngleUnitsPerDegree = 1e5 * 3.14159265358979323846 / 180.0;

// hdmv axes as head rotation FAPs: yaw 49, pitch 48, roll 50.
constexpr int kAxisFap[3] = {49, 48, 50};

}  // namespace

// A move's target, its name kept once in the tree.
std::uint32_t FmlReader::target_number(const std::string& name) {
  const std::uint32_t number = target_names_.number(name);
  if (number == tree_.targets.size()) tree_.targets.push_back(name);
  return number;
}

ScheduleNode FmlReader::add_leaf(const xmlNode* node, FmlLeaf leaf, Timing timing) {
  leaf.where = doc_.where(node);
  const std::size_t id = tree_.leaves.size();
  const Location where = leaf.where;
  tree_.leaves.push_back(std::move(leaf));
  return remember(ScheduleNode::leaf(id, timing, where), node);
}

// A move that cannot be animated (an unknown type) keeps its place in time as a wait.
ScheduleNode FmlReader::as_wait(const xmlNode* node, const FmlTiming& timing, Diagnostic warning) {
  result_.warnings.push_back(std::move(warning));
  return add_leaf(node, FmlLeaf{}, move_timing(timing, 1.0));
}

std::optional<double> FmlReader::value_attribute(const xmlNode* node, double fallback) {
  const auto text = spelled(node, "val", {"value"});
  if (!text) return fallback;
  const auto v = number(*text);
  if (!v) fail(doc_.error(codes::fml::not_a_number, node, value_name(node), "'" + *text + "' is not a number"));
  return v;
}

std::optional<ScheduleNode> FmlReader::move(const xmlNode* node, const FmlTiming& timing) {
  const std::string_view name = xml::local_name(node);
  if (name == "talk") return talk(node, timing);
  check_text(node);
  if (name == "wait") {
    check_attributes(node, kTiming, {"ev_val", "event_value"});
    return add_leaf(node, FmlLeaf{}, move_timing(timing, 1.0));
  }
  if (name == "hdmv") {
    check_attributes(node, kTiming, {"type", "dir", "val", "value", "ev_val", "event_value"});
  } else {
    check_attributes(node, kTiming, {"type", "val", "value", "ev_val", "event_value"});
  }
  const auto type = name == "hdmv" ? spelled(node, "type", {"dir"}) : xml::attribute(node, "type");
  if (!type) {
    fail(doc_.error(codes::fml::missing_attribute, node, std::string(name) + " needs type"));
    return std::nullopt;
  }
  if (name == "expr") return expr(node, timing, *type);
  if (name == "hdmv") return hdmv(node, timing, *type);
  if (name == "fap") return fap(node, timing, *type);
  return param(node, timing, *type);
}

std::optional<ScheduleNode> FmlReader::expr(const xmlNode* node, const FmlTiming& timing, const std::string& type) {
  const auto expression = expression_number(type);
  if (!expression) {
    return as_wait(node, timing,
                   doc_.warning(node, "type",
                                "expression type '" + type +
                                    "' is not one fapc knows (smile, sadness, anger, "
                                    "fear, disgust, surprise, normal or 0-6): it waits"));
  }
  FmlLeaf leaf;
  if (*expression == 0) {
    leaf.kind = FmlLeaf::Kind::normal;
    return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
  }
  auto percent = value_attribute(node, 100);
  if (!percent) return std::nullopt;
  if (*percent < 0 || *percent > 100) {
    result_.warnings.push_back(doc_.warning(
        node, value_name(node), "expression val " + format_number(*percent) + " is outside 0-100 (%) and was clamped"));
    percent = std::clamp(*percent, 0.0, 100.0);
  }
  leaf.kind = FmlLeaf::Kind::move;
  const std::string target = "expression." + std::string(expression_name(*expression));
  leaf.target = target_number(target);
  leaf.value = *percent * 63.0 / 100.0;
  expressions_.insert(target);
  return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
}

std::optional<ScheduleNode> FmlReader::hdmv(const xmlNode* node, const FmlTiming& timing, const std::string& type) {
  const char* type_name = xml::attribute(node, "type") ? "type" : "dir";
  const auto axis = head_axis(type);
  if (!axis) {
    return as_wait(
        node, timing,
        doc_.warning(node, type_name, "head movement type '" + type + "' is not yaw, pitch, roll or 0-2: it waits"));
  }
  auto degrees = value_attribute(node, 0);
  if (!degrees) return std::nullopt;
  const double clamped = std::clamp(*degrees, limits_.min[*axis], limits_.max[*axis]);
  if (clamped != *degrees) {
    result_.warnings.push_back(doc_.warning(
        node, value_name(node),
        "head movement of " + format_number(*degrees) + " degrees is beyond the model's range and was clamped"));
  }
  FmlLeaf leaf;
  leaf.kind = FmlLeaf::Kind::move;
  leaf.target = target_number(std::string(find_fap(kAxisFap[*axis])->name));
  leaf.value = clamped * kAngleUnitsPerDegree;
  return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
}

std::optional<ScheduleNode> FmlReader::fap(const xmlNode* node, const FmlTiming& timing, const std::string& type) {
  const FapInfo* info = find_fap_by_name_or_number(trim(type));
  if (!info) {
    std::string closest;
    for (const std::string_view n : closest_fap_names(trim(type)))
      closest += (closest.empty() ? "" : ", ") + std::string(n);
    fail(doc_.error(codes::fml::bad_fap, node, "type",
                    quoted_name(type) + " is not a FAP number (3-68) or name" +
                        (closest.empty() ? std::string() : "; did you mean " + closest + "?")));
    return std::nullopt;
  }
  if (info->number < 3) {
    fail(doc_.error(
        codes::fml::bad_fap, node, "type",
        "FAP " + std::to_string(info->number) + " is not animated with fap: use talk (visemes) or expr (expressions)"));
    return std::nullopt;
  }
  const auto value = value_attribute(node, 0);
  if (!value) return std::nullopt;
  FmlLeaf leaf;
  leaf.kind = FmlLeaf::Kind::move;
  leaf.target = target_number(std::string(info->name));
  leaf.value = *value;
  return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
}

std::optional<ScheduleNode> FmlReader::param(const xmlNode* node, const FmlTiming& timing, const std::string& type) {
  const std::string name = trim(type);
  if (resolve_target(name, *profile_).empty() || weight_target(name)) {
    // Parameters are system-dependent (the paper's eye-wink): what the profile does not map waits.
    return as_wait(
        node, timing,
        doc_.warning(node, "type",
                     unknown_parameter_message(name, *profile_) + " (param names come from the profile): it waits"));
  }
  const auto value = value_attribute(node, 0);
  if (!value) return std::nullopt;
  FmlLeaf leaf;
  leaf.kind = FmlLeaf::Kind::move;
  leaf.target = target_number(name);
  leaf.value = *value;
  return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
}

}  // namespace fapc::fml::reading

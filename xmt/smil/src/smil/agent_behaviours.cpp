#include "smil/agent_behaviours.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

#include "fapc/vocabulary/mapping_table.hpp"
#include "fapc/xml/text.hpp"

namespace fapc::smil {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

bml::Behaviour behaviour_at(const Location& where, bool shift) {
  bml::Behaviour b;
  b.where = where;
  b.shift = shift;
  return b;
}

// A turn of the eyes (a gaze of influence EYES) or of the head, by direction and angle.
bml::Behaviour turn(const Action& action, std::string direction, double degrees) {
  bml::Behaviour b = behaviour_at(action.where, action.shift);
  b.element = "action";
  b.kind = action.channel == Channel::head ? bml::BehaviourKind::head_direction : bml::BehaviourKind::gaze;
  b.influence = "EYES";
  b.offset_direction = std::move(direction);
  b.offset_angle = degrees;
  return b;
}

// The largest turn at intensity 1 (docs/smil.md): the eyes' comfortable range is some 30 degrees
// either way before the head joins in; a head turned 30 degrees looks clearly aside.
constexpr double kTurnDegrees = 30;

}  // namespace

const std::vector<AffectRow>& affect_rows() {
  static const std::vector<AffectRow> rows = [] {
    std::vector<AffectRow> out;
    for (const std::vector<std::string_view>& cells : vocabulary::bundled_table_cells("smil_affects.tsv")) {
      if (cells.size() != 4) continue;
      AffectRow row{std::string(cells[0]), std::string(cells[1]), 1, std::string(cells[3])};
      std::from_chars(cells[2].data(), cells[2].data() + cells[2].size(), row.amount);
      out.push_back(std::move(row));
    }
    return out;
  }();
  return rows;
}

std::vector<bml::Behaviour> affect_behaviours(const std::string& affect, double intensity, bool shift,
                                              const Location& where) {
  std::vector<bml::Behaviour> out;
  const std::string name = lower(xml::trim(affect));
  for (const AffectRow& row : affect_rows()) {
    if (lower(row.affect) != name) continue;
    bml::Behaviour b = behaviour_at(where, shift);
    b.element = "speech-animation";
    b.amount = row.amount * intensity;
    if (row.behaviour.starts_with("AU")) {
      b.kind = bml::BehaviourKind::face_facs;
      std::from_chars(row.behaviour.data() + 2, row.behaviour.data() + row.behaviour.size(), b.au);
    } else {
      b.kind = bml::BehaviourKind::face_lexeme;
      b.lexeme = row.behaviour;
    }
    out.push_back(std::move(b));
  }
  return out;
}

Channel channel_of(const std::string& channel) {
  const std::string c = lower(xml::trim(channel));
  if (c.empty() || c.ends_with("eyes") || c.ends_with("eye") || c.ends_with("gaze")) return Channel::eyes;
  if (c.ends_with("head")) return Channel::head;
  return Channel::other;
}

std::vector<bml::Behaviour> action_behaviours(const Action& action, std::string& why) {
  const std::string type = lower(xml::trim(action.type));
  if (type == "turning") {
    if (action.params.size() != 1) {
      why = "a turning action takes one parameter (LookLeft, LookRight, LookUp, LookDown)";
      return {};
    }
    const std::string p = lower(xml::trim(action.params[0]));
    // LEFT and RIGHT are the character's own, as BML's offsetDirection (docs/bml.md).
    static const std::pair<const char*, const char*> kLooks[] = {
        {"lookleft", "LEFT"}, {"lookright", "RIGHT"}, {"lookup", "UP"}, {"lookdown", "DOWN"}};
    for (const auto& [word, direction] : kLooks)
      if (p == word) {
        std::vector<bml::Behaviour> out;
        out.push_back(turn(action, direction, kTurnDegrees * action.intensity));
        return out;
      }
    why = "turning '" + action.params[0] + "' is not a direction fapc knows (LookLeft, LookRight, LookUp, LookDown)";
    return {};
  }
  if (type == "pointing") {
    // Three numbers: the point looked at, x to the character's left, y up, z ahead (docs/smil.md).
    double xyz[3] = {0, 0, 0};
    bool numbers = action.params.size() == 3;
    for (std::size_t i = 0; numbers && i < 3; ++i) {
      const auto v = xml::decimal(xml::trim(action.params[i]));
      numbers = v.has_value();
      if (numbers) xyz[i] = *v;
    }
    if (!numbers || (xyz[0] == 0 && xyz[1] == 0 && xyz[2] == 0)) {
      why = "a pointing action takes three numbers, the point looked at (x left, y up, z ahead), not all 0";
      return {};
    }
    constexpr double kDegrees = 180 / std::numbers::pi;
    const double yaw = std::atan2(xyz[0], xyz[2]) * kDegrees;
    const double pitch = std::atan2(xyz[1], std::hypot(xyz[0], xyz[2])) * kDegrees;
    std::vector<bml::Behaviour> out;
    if (yaw != 0) out.push_back(turn(action, yaw > 0 ? "LEFT" : "RIGHT", std::abs(yaw)));
    if (pitch != 0) out.push_back(turn(action, pitch > 0 ? "UP" : "DOWN", std::abs(pitch)));
    return out;
  }
  if (type == "blink" || type == "blinking") {
    bml::Behaviour b = behaviour_at(action.where, false);
    b.element = "action";
    b.kind = bml::BehaviourKind::face_lexeme;
    b.lexeme = "CLOSE_EYES";
    b.amount = action.intensity;
    std::vector<bml::Behaviour> out;
    out.push_back(std::move(b));
    return out;
  }
  why = "action-type '" + action.type + "' is not one fapc draws (turning, pointing, blink)";
  return {};
}

}  // namespace fapc::smil

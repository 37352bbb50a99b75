#include "fapc/mpeg4/scene.hpp"

#include <utility>

#include "bifs_nodes.hpp"
#include "fapc/codec/fap_table.hpp"

namespace fapc::xmt {

namespace {

// The six FAPs whose BIFS field name is not their 14496-2 name (docs/fap-table.md section 5,
// checked against GPAC's FAP node table in tests/xmt/scene_test.cpp).
constexpr std::pair<int, std::string_view> kRenamedFapFields[] = {
    {6, "stretch_l_corner"}, {7, "stretch_r_corner"},     {10, "lower_b_lip_lm"},
    {11, "lower_b_lip_rm"},  {53, "stretch_l_cornerlip"}, {54, "stretch_r_cornerlip"},
};

SceneNode node(std::string type, std::string def_name = {}, std::vector<SceneField> fields = {}) {
  return SceneNode{std::move(type), std::move(def_name), std::move(fields)};
}

bool is_mf_node_field(const std::string& type, const std::string& field) {
  const bifs::NodeSpec* spec = bifs::find_node(type);
  if (!spec) return false;
  for (const bifs::FieldSpec& f : spec->fields)
    if (f.name == field) return f.kind == bifs::FieldKind::mf_node;
  return false;
}

SceneField children(std::string name, std::vector<SceneNode> nodes) {
  return SceneField{std::move(name), std::move(nodes)};
}

}  // namespace

const SceneField* SceneNode::field(std::string_view name) const {
  for (const SceneField& f : fields)
    if (f.name == name) return &f;
  return nullptr;
}

std::string scene_text(const SceneNode& node) {
  std::string out = node.type + (node.def_name.empty() ? "" : " DEF " + node.def_name) + " {";
  for (const SceneField& f : node.fields) {
    out += ' ' + f.name + ' ';
    if (const auto* nodes = std::get_if<std::vector<SceneNode>>(&f.value)) {
      const bool list = is_mf_node_field(node.type, f.name);
      if (list) out += "[ ";
      for (const SceneNode& child : *nodes) out += scene_text(child) + ' ';
      if (list)
        out += ']';
      else
        out.pop_back();
    } else if (const auto* i = std::get_if<std::int32_t>(&f.value)) {
      out += std::to_string(*i);
    } else if (const auto* b = std::get_if<bool>(&f.value)) {
      out += *b ? "TRUE" : "FALSE";
    } else if (const auto* urls = std::get_if<std::vector<ObjectUrl>>(&f.value)) {
      out += '[';
      for (const ObjectUrl& u : *urls) out += " \"od:" + std::to_string(u.od_id) + '"';
      out += " ]";
    } else {
      out += std::to_string(std::get<float>(f.value));
    }
  }
  return out + " }";
}

std::string_view fap_field_name(int fap) {
  for (const auto& [number, name] : kRenamedFapFields)
    if (number == fap) return name;
  const FapInfo* info = find_fap(fap);
  return info && fap >= 3 ? info->name : std::string_view{};
}

int fap_for_field_name(std::string_view name) {
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (fap_field_name(fap) == name) return fap;
  return 0;
}

std::vector<SceneField> viseme_fields(const VisemeFields& v) {
  return {{"viseme_select1", v.select1},
          {"viseme_select2", v.select2},
          {"viseme_blend", v.blend},
          {"viseme_def", v.def != 0}};
}

std::vector<SceneField> expression_fields(const ExpressionFields& e) {
  return {{"expression_select1", e.select1}, {"expression_intensity1", e.intensity1},
          {"expression_select2", e.select2}, {"expression_intensity2", e.intensity2},
          {"init_face", e.init_face != 0},   {"expression_def", e.def != 0}};
}

SceneNode face_scene(const FapFrame* initial) {
  SceneNode fap = node("FAP", std::string(kFapDefName));
  if (initial) {
    // Viseme and Expression nodes always exist in this form, so that timed commands can address
    // their fields by DEF name even when the first frame does not mask FAP 1 or 2.
    const FapFrame& f = *initial;
    fap.fields.push_back(children("viseme", {node("Viseme", std::string(kVisemeDefName),
                                                  f.has(1) ? viseme_fields(f.viseme) : std::vector<SceneField>{})}));
    fap.fields.push_back(
        children("expression", {node("Expression", std::string(kExpressionDefName),
                                     f.has(2) ? expression_fields(f.expression) : std::vector<SceneField>{})}));
    for (int number = 3; number <= kFapCount; ++number)
      if (f.has(number)) fap.fields.push_back({std::string(fap_field_name(number)), f.value(number)});
  }
  SceneNode shape = node("Shape", {}, {children("geometry", {node("Sphere")})});
  SceneNode face = node("Face", std::string(kFaceDefName),
                        {children("fap", {std::move(fap)}), children("renderedFace", {std::move(shape)})});
  return node("Group", {}, {children("children", {std::move(face)})});
}

SceneNode with_sound(SceneNode scene, std::uint16_t audio_od_id) {
  SceneNode source = node("AudioSource", {}, {{"url", std::vector<ObjectUrl>{{audio_od_id}}}});
  SceneNode sound = node("Sound2D", {}, {children("source", {std::move(source)})});
  for (SceneField& f : scene.fields)
    if (auto* nodes = std::get_if<std::vector<SceneNode>>(&f.value); nodes && f.name == "children")
      nodes->push_back(std::move(sound));
  return scene;
}

}  // namespace fapc::xmt

#include "bifs_nodes.hpp"

#include <string>

#include "fapc/codec/fap_table.hpp"
#include "fapc/mpeg4/scene.hpp"

namespace fapc::xmt::bifs {

namespace {

std::vector<FieldSpec> fap_node_fields() {
  std::vector<FieldSpec> fields = {{"viseme", FieldKind::sf_node, Ndt::viseme},
                                   {"expression", FieldKind::sf_node, Ndt::expression}};
  for (int fap = 3; fap <= kFapCount; ++fap)
    fields.push_back({fap_field_name(fap), FieldKind::sf_int32, Ndt::top, kUninitialised});
  return fields;
}

const std::vector<NodeSpec>& node_table() {
  static const std::vector<NodeSpec> table = {
      {"Group", {{"children", FieldKind::mf_node, Ndt::node3d}}},
      {"Face",
       {{"fap", FieldKind::sf_node, Ndt::fap},
        {"fdp", FieldKind::sf_node, Ndt::fdp},
        {"fit", FieldKind::sf_node, Ndt::fit},
        {"ttsSource", FieldKind::sf_node, Ndt::audio},
        {"renderedFace", FieldKind::mf_node, Ndt::node3d}}},
      {"FAP", fap_node_fields()},
      {"Viseme",
       {{"viseme_select1", FieldKind::sf_int32},
        {"viseme_select2", FieldKind::sf_int32},
        {"viseme_blend", FieldKind::sf_int32},
        {"viseme_def", FieldKind::sf_bool}}},
      {"Expression",
       {{"expression_select1", FieldKind::sf_int32},
        {"expression_intensity1", FieldKind::sf_int32},
        {"expression_select2", FieldKind::sf_int32},
        {"expression_intensity2", FieldKind::sf_int32},
        {"init_face", FieldKind::sf_bool},
        {"expression_def", FieldKind::sf_bool}}},
      {"Shape", {{"appearance", FieldKind::sf_node, Ndt::appearance}, {"geometry", FieldKind::sf_node, Ndt::geometry}}},
      {"Sphere", {{"radius", FieldKind::sf_float, Ndt::top, 0, 1.0F}}},
      // The voice. Fields the project never sets are listed for their place in DEF order only
      // (their kinds beyond these are not coded: the encoder refuses them, the decoder names them).
      {"Sound2D",
       {{"intensity", FieldKind::sf_float, Ndt::top, 0, 1.0F},
        {"location", FieldKind::uncoded},
        {"source", FieldKind::sf_node, Ndt::audio},
        {"spatialize", FieldKind::sf_bool}}},
      {"AudioSource",
       {{"children", FieldKind::mf_node, Ndt::audio},
        {"url", FieldKind::mf_url},
        {"pitch", FieldKind::sf_float, Ndt::top, 0, 1.0F},
        {"speed", FieldKind::sf_float, Ndt::top, 0, 1.0F},
        {"startTime", FieldKind::uncoded},
        {"stopTime", FieldKind::uncoded},
        {"numChan", FieldKind::sf_int32, Ndt::top, 1},
        {"phaseGroup", FieldKind::uncoded}}},
  };
  return table;
}

// Version 1 codes: position in the standard's alphabetical NDT table plus one.
const std::vector<NdtSpec>& ndt_table() {
  static const std::vector<NdtSpec> table = {
      {Ndt::top, "SFTopNode", 3, {{"Group", 1}}},
      {Ndt::node3d, "SF3DNode", 6, {{"Face", 14}, {"Group", 17}, {"Shape", 38}, {"Sound2D", 40}}},
      {Ndt::fap, "SFFAPNode", 1, {{"FAP", 1}}},
      {Ndt::viseme, "SFVisemeNode", 1, {{"Viseme", 1}}},
      {Ndt::expression, "SFExpressionNode", 1, {{"Expression", 1}}},
      {Ndt::geometry, "SFGeometryNode", 5, {{"Sphere", 16}}},
      {Ndt::appearance, "SFAppearanceNode", 1, {}},
      {Ndt::fdp, "SFFDPNode", 1, {}},
      {Ndt::fit, "SFFITNode", 1, {}},
      {Ndt::audio, "SFAudioNode", 3, {{"AudioSource", 6}}},
  };
  return table;
}

}  // namespace

const NodeSpec* find_node(std::string_view name) {
  for (const NodeSpec& n : node_table())
    if (n.name == name) return &n;
  return nullptr;
}

const NdtSpec& ndt_spec(Ndt ndt) {
  for (const NdtSpec& s : ndt_table())
    if (s.ndt == ndt) return s;
  return ndt_table().front();  // unreachable: every Ndt has a row
}

std::uint32_t node_code(Ndt ndt, std::string_view node) {
  for (const NdtMember& m : ndt_spec(ndt).members)
    if (m.node == node) return m.code;
  return 0;
}

const NodeSpec* node_for_code(Ndt ndt, std::uint32_t code) {
  for (const NdtMember& m : ndt_spec(ndt).members)
    if (m.code == code) return find_node(m.node);
  return nullptr;
}

int bit_size(std::uint32_t max_value) {
  int k = 0;
  while (k < 32 && max_value > ((std::uint32_t{1} << k) - 1)) ++k;
  return k;
}

}  // namespace fapc::xmt::bifs

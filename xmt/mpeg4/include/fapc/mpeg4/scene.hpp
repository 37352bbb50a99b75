// A scene graph as plain values: the small subset of MPEG-4 scene nodes the project writes (and
// reads back), shared by the BIFS coder and the XMT-A writer so both describe the same scene.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc::xmt {

struct SceneField;

struct SceneNode {
  std::string type;                // "Group", "Face", "FAP", ...
  std::string def_name;            // empty when the node is not DEF'd
  std::vector<SceneField> fields;  // only fields that differ from their defaults, in node order

  const SceneField* field(std::string_view name) const;
  friend bool operator==(const SceneNode&, const SceneNode&);
};

// An SFURL that names an object descriptor ("od:11" in XMT-A): how a scene's media nodes
// (AudioSource) find their stream.
struct ObjectUrl {
  std::uint16_t od_id = 0;  // 10 bits
  friend bool operator==(const ObjectUrl&, const ObjectUrl&) = default;
};

// SFInt32, SFBool, SFFloat, node fields (SFNode: one node; MFNode: any number), or an MFURL of
// object descriptor URLs.
using FieldValue = std::variant<std::int32_t, bool, float, std::vector<SceneNode>, std::vector<ObjectUrl>>;

struct SceneField {
  std::string name;
  FieldValue value;
  friend bool operator==(const SceneField&, const SceneField&) = default;
};

inline bool operator==(const SceneNode& a, const SceneNode& b) {
  return a.type == b.type && a.def_name == b.def_name && a.fields == b.fields;
}

// The DEF names the project gives its face scene's nodes (targets of timed Replace commands).
inline constexpr std::string_view kFaceDefName = "FACE";
inline constexpr std::string_view kFapDefName = "PARAMS";
inline constexpr std::string_view kVisemeDefName = "VISEME";
inline constexpr std::string_view kExpressionDefName = "EXPRESSION";

// The fixed scene: Group { children [ Face DEF FACE { fap FAP DEF PARAMS { ... }
// renderedFace [ Shape { geometry Sphere {} } ] } ] }. With `initial`, the FAP node starts with
// that frame's masked values and carries DEF'd Viseme and Expression nodes (the form the timed
// Replace commands animate); without it, the FAP node is empty (an FBA stream drives it).
SceneNode face_scene(const FapFrame* initial = nullptr);

// The same scene with the face's voice beside it: the Group's children gain
// Sound2D { source AudioSource { url "od:OD_ID" } }, the audio stream's object descriptor.
SceneNode with_sound(SceneNode scene, std::uint16_t audio_od_id);

// A one-line, VRML-like rendering for `fapc info`: "Group { children [ Face DEF FACE { ... } ] }".
std::string scene_text(const SceneNode& node);

// The BIFS `FAP` node's field name for FAPs 3..68. Six differ from the 14496-2 names used
// elsewhere in the project (docs/fap-table.md section 5): 6, 7, 10, 11, 53 and 54.
std::string_view fap_field_name(int fap);
// The FAP number of a FAP-node field name, or 0.
int fap_for_field_name(std::string_view name);

// Every field of the Viseme (FAP 1) and Expression (FAP 2) nodes, in node order, defaults
// included; the `_def` and `init_face` flags become booleans.
std::vector<SceneField> viseme_fields(const VisemeFields& v);
std::vector<SceneField> expression_fields(const ExpressionFields& e);

}  // namespace fapc::xmt

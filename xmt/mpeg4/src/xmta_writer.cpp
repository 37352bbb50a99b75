// The XMT-A writer. The header mirrors what the MP4 writer puts in the iods and the system
// tracks' esds boxes (same IDs, profile-levels and BIFSConfig), so that MP4Box builds the same
// layout from this document as fapc writes directly.
#include "fapc/mpeg4/xmta_writer.hpp"

#include <charconv>
#include <map>

#include "fapc/mpeg4/bifs.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "fapc/mpeg4/object_descriptors.hpp"
#include "fapc/mpeg4/scene.hpp"
#include "xml_out.hpp"

namespace fapc::xmt {

namespace {

std::string number(long long v) { return std::to_string(v); }

std::string value_text(const FieldValue& v) {
  if (const auto* i = std::get_if<std::int32_t>(&v)) return number(*i);
  if (const auto* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  if (const auto* urls = std::get_if<std::vector<ObjectUrl>>(&v)) {  // an MFURL: quoted strings
    std::string out;
    for (const ObjectUrl& u : *urls) out += (out.empty() ? "\"od:" : " \"od:") + number(u.od_id) + '"';
    return out;
  }
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, std::get<float>(v)).ptr;
  return std::string(buffer, end);
}

// A node: scalar fields as attributes, node fields as child elements named after the field.
void write_node(XmlOut& xml, const SceneNode& node) {
  XmlAttributes attributes;
  if (!node.def_name.empty()) attributes.emplace_back("DEF", node.def_name);
  bool has_children = false;
  for (const SceneField& f : node.fields) {
    if (std::holds_alternative<std::vector<SceneNode>>(f.value))
      has_children = true;
    else
      attributes.emplace_back(f.name, value_text(f.value));
  }
  if (!has_children) {
    xml.empty(node.type, attributes);
    return;
  }
  xml.open(node.type, attributes);
  for (const SceneField& f : node.fields) {
    const auto* children = std::get_if<std::vector<SceneNode>>(&f.value);
    if (!children) continue;
    xml.open(f.name);
    for (const SceneNode& child : *children) write_node(xml, child);
    xml.close();
  }
  xml.close();
}

// "%00%00%01%B0...": how GPAC writes a DecoderSpecificInfo's bytes.
std::string percent_bytes(const Bytes& bytes) {
  static const char* digits = "0123456789ABCDEF";
  std::string out;
  for (std::uint8_t b : bytes) out += {'%', digits[b >> 4], digits[b & 15]};
  return out;
}

void write_sl_config(XmlOut& xml) {
  xml.open("slConfigDescr");
  xml.empty("SLConfigDescriptor", {{"predefined", number(kSlPredefinedMp4)}});
  xml.close();
}

void write_system_stream(XmlOut& xml, const std::string& es_id, std::uint32_t binary_id, std::uint8_t stream_type,
                         bool bifs_config) {
  xml.open("ES_Descriptor", {{"ES_ID", es_id}, {"binaryID", number(binary_id)}});
  xml.open("decConfigDescr");
  const XmlAttributes types = {{"streamType", number(stream_type)}, {"objectTypeIndication", number(kSystemsV1Object)}};
  if (!bifs_config) {
    xml.empty("DecoderConfigDescriptor", types);
  } else {
    const BifsConfig config;
    xml.open("DecoderConfigDescriptor", types);
    xml.open("decSpecificInfo");
    xml.open("BIFSConfig", {{"useNames", "true"}});
    xml.open("commandStream", {{"pixelMetric", config.pixel_metric ? "true" : "false"}});
    xml.empty("size", {{"pixelWidth", number(config.width)}, {"pixelHeight", number(config.height)}});
    xml.close();
    xml.close();
    xml.close();
    xml.close();
  }
  xml.close();
  write_sl_config(xml);
  xml.close();
}

// XMT-A, Header with the initial object descriptor, and Body; leaves Body open.
void write_head(XmlOut& xml, const ProfileLevels& pl, bool with_od_stream) {
  xml.open("XMT-A", {{"xmlns", kXmtaNamespace}});
  xml.open("Header");
  xml.open("InitialObjectDescriptor", {{"objectDescriptorID", "od1"}, {"binaryID", "1"}});
  xml.empty("Profiles", {{"ODProfileLevelIndication", number(pl.od)},
                         {"sceneProfileLevelIndication", number(pl.scene)},
                         {"audioProfileLevelIndication", number(pl.audio)},
                         {"visualProfileLevelIndication", number(pl.visual)},
                         {"graphicsProfileLevelIndication", number(pl.graphics)}});
  xml.open("Descr");
  xml.open("esDescr");
  write_system_stream(xml, "scene", kSceneTrackId, kSceneDescriptionStream, true);
  if (with_od_stream) write_system_stream(xml, "od", kOdTrackId, kObjectDescriptorStream, false);
  xml.close();
  xml.close();
  xml.close();
  xml.close();
  xml.open("Body");
}

void write_scene_replace(XmlOut& xml, const SceneNode& scene) {
  xml.open("Replace");
  xml.open("Scene");
  write_node(xml, scene);
  xml.close();
  xml.close();
}

// One ObjectDescriptor holding one ES_Descriptor, inside an open OD command.
void write_object_descriptor(XmlOut& xml, std::uint16_t od_id, const std::string& es_name, std::uint32_t es_id,
                             std::uint8_t stream_type, std::uint8_t object_type, const Bytes& dsi,
                             const std::string& stream_source) {
  const std::string id = number(od_id);
  xml.open("ObjectDescriptor", {{"objectDescriptorID", "od" + id}, {"binaryID", id}});
  xml.open("Descr");
  xml.open("esDescr");
  xml.open("ES_Descriptor", {{"ES_ID", es_name}, {"binaryID", number(es_id)}});
  xml.open("decConfigDescr");
  xml.open("DecoderConfigDescriptor",
           {{"streamType", number(stream_type)}, {"objectTypeIndication", number(object_type)}});
  xml.open("decSpecificInfo");
  xml.empty("DecoderSpecificInfo", {{"src", "data:application/octet-string," + percent_bytes(dsi)}});
  xml.close();
  xml.close();
  xml.close();
  write_sl_config(xml);
  if (!stream_source.empty()) xml.empty("StreamSource", {{"url", stream_source}});
  xml.close();
  for (int i = 0; i < 3; ++i) xml.close();
}

void write_object_descriptors(XmlOut& xml, const Bytes& dsi, const std::string& stream_source, const XmtaAudio* audio) {
  xml.open("ObjectDescriptorUpdate");
  xml.open("OD");
  write_object_descriptor(xml, kFbaObjectDescriptorId, "fba", kFbaTrackId, kVisualStream, kVisual14496_2Object, dsi,
                          stream_source);
  if (audio)
    write_object_descriptor(xml, kAudioObjectDescriptorId, "voice", kAudioTrackId, kAudioStream, kAudio14496_3Object,
                            audio->decoder_specific_info, audio->stream_source);
  xml.close();
  xml.close();
}

// Seconds as plain decimals (GPAC reads `begin` with atof): up to microseconds, no trailing zeros.
std::string seconds_text(std::int64_t frame, int fps) {
  const std::int64_t micros = (frame * 1000000 + fps / 2) / fps;
  std::string text = std::to_string(micros / 1000000);
  if (const std::int64_t fraction = micros % 1000000; fraction != 0) {
    std::string digits = std::to_string(fraction);
    digits.insert(0, 6 - digits.size(), '0');
    while (digits.back() == '0') digits.pop_back();
    text += '.' + digits;
  }
  return text;
}

// The fields a frame sets, per DEF'd node, in node order.
using NodeValues = std::map<std::string, std::vector<SceneField>>;

NodeValues frame_values(const FapFrame& frame) {
  NodeValues values;
  if (frame.has(1)) values[std::string(kVisemeDefName)] = viseme_fields(frame.viseme);
  if (frame.has(2)) values[std::string(kExpressionDefName)] = expression_fields(frame.expression);
  auto& faps = values[std::string(kFapDefName)];
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (frame.has(fap)) faps.push_back({std::string(fap_field_name(fap)), frame.value(fap)});
  return values;
}

}  // namespace

std::string write_xmta_fba_scene(const Bytes& dsi, const std::string& stream_source, const XmtaAudio* audio) {
  ProfileLevels profiles;
  profiles.od = 0x01;
  profiles.visual = fba_profile_level(dsi).ok() ? *fba_profile_level(dsi) : kSimpleFbaL1;
  if (audio) profiles.audio = aac_profile_level(audio->sample_rate);
  XmlOut xml;
  write_head(xml, profiles, true);
  xml.open("par", {{"begin", "0"}, {"isRAP", "yes"}});
  write_object_descriptors(xml, dsi, stream_source, audio);
  write_scene_replace(xml, audio ? with_sound(face_scene(), kAudioObjectDescriptorId) : face_scene());
  xml.close();
  xml.close();
  xml.close();
  return xml.take();
}

std::string write_xmta_commands(const FapSequence& sequence) {
  const std::vector<FapFrame>& frames = sequence.frames;
  const bool first_at_zero = !frames.empty() && frames.front().number == 0;
  const FapFrame empty_frame;
  const FapFrame& initial = first_at_zero ? frames.front() : empty_frame;

  // What each addressed field holds now: the initial scene's values, then every change.
  std::map<std::pair<std::string, std::string>, std::string> state;
  for (const auto& [def, fields] : frame_values(initial))
    for (const SceneField& f : fields) state[{def, f.name}] = value_text(f.value);
  for (const SceneField& f : viseme_fields({}))
    state.try_emplace({std::string(kVisemeDefName), f.name}, value_text(f.value));
  for (const SceneField& f : expression_fields({}))
    state.try_emplace({std::string(kExpressionDefName), f.name}, value_text(f.value));

  XmlOut xml;
  write_head(xml, ProfileLevels{}, false);
  xml.open("par", {{"begin", "0"}, {"isRAP", "yes"}});
  write_scene_replace(xml, face_scene(&initial));
  xml.close();
  for (std::size_t i = first_at_zero ? 1 : 0; i < frames.size(); ++i) {
    std::vector<XmlAttributes> commands;
    for (const auto& [def, fields] : frame_values(frames[i]))
      for (const SceneField& f : fields) {
        std::string& held = state[{def, f.name}];
        const std::string text = value_text(f.value);
        if (held == text) continue;
        held = text;
        commands.push_back({{"atNode", def}, {"atField", f.name}, {"value", text}});
      }
    if (commands.empty()) continue;
    xml.open("par", {{"begin", seconds_text(frames[i].number, sequence.fps)}});
    for (const XmlAttributes& c : commands) xml.empty("Replace", c);
    xml.close();
  }
  xml.close();
  xml.close();
  return xml.take();
}

}  // namespace fapc::xmt

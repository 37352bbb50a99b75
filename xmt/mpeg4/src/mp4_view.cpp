// The project's view of an MP4 file: which track is the scene, the object descriptors, the FBA
// stream. Built on the generic reader; every "not found" names what was looked for.
#include "fapc/mpeg4/mp4_reader.hpp"

namespace fapc::xmt {

namespace {

const Mp4Track* find_stream(const Mp4File& mp4, std::uint8_t stream_type) {
  for (const Mp4Track& t : mp4.tracks)
    if (t.es && t.es->config.stream_type == stream_type) return &t;
  return nullptr;
}

Diagnostic file_error(const Mp4File& mp4, std::uint64_t offset, const std::string& message) {
  return make_error(Location::binary(mp4.file, static_cast<std::int64_t>(offset)), message);
}

}  // namespace

Result<Mp4SceneView> read_scene(const Mp4File& mp4) {
  const Mp4Track* t = find_stream(mp4, kSceneDescriptionStream);
  if (!t) return file_error(mp4, 0, "no scene description track");
  const std::uint8_t oti = t->es->config.object_type;
  if (oti != 1 && oti != 2)
    return file_error(mp4, t->es_offset, "scene track " + std::to_string(t->id) + " is not BIFS (objectTypeIndication " +
                                             std::to_string(oti) + ")");
  if (t->samples.empty()) return file_error(mp4, t->box_offset, "scene track has no access unit");
  Mp4SceneView view;
  view.track_id = t->id;
  auto config = decode_bifs_config(t->es->config.specific_info, t->es_offset, mp4.file);
  if (!config) return config.error();
  view.config = *config;
  const Mp4Sample& first = t->samples.front();
  auto scene = decode_scene_replace(mp4.sample_bytes(first), view.config, first.offset, mp4.file);
  if (!scene) return scene.error();
  view.scene = std::move(*scene);
  return view;
}

Result<std::vector<Mp4ObjectView>> read_object_descriptors(const Mp4File& mp4) {
  const Mp4Track* t = find_stream(mp4, kObjectDescriptorStream);
  if (!t) return file_error(mp4, 0, "no object descriptor track");
  if (t->samples.empty()) return file_error(mp4, t->box_offset, "object descriptor track has no access unit");
  const Mp4Sample& first = t->samples.front();
  auto ods = decode_object_descriptor_updates(mp4.sample_bytes(first), first.offset, mp4.file);
  if (!ods) return ods.error();
  std::vector<Mp4ObjectView> out;
  for (ObjectDescriptor& od : *ods) {
    Mp4ObjectView view;
    for (std::uint16_t ref : od.es_id_refs) {
      if (ref == 0 || ref > t->mpod.size())
        return file_error(mp4, first.offset, "object descriptor " + std::to_string(od.od_id) + " refers to stream " +
                                                 std::to_string(ref) + " of the OD track's " +
                                                 std::to_string(t->mpod.size()) + " 'mpod' references");
      view.track_ids.push_back(t->mpod[ref - 1]);
    }
    view.od = std::move(od);
    out.push_back(std::move(view));
  }
  return out;
}

const Mp4Track* find_fba_track(const Mp4File& mp4) {
  for (const Mp4Track& t : mp4.tracks)
    if (t.es && t.es->config.stream_type == kVisualStream &&
        t.es->config.object_type == kVisual14496_2Object && declares_fba_object(t.es->config.specific_info))
      return &t;
  return nullptr;
}

Result<FbaTrackInput> read_fba_track(const Mp4File& mp4) {
  const Mp4Track* t = find_fba_track(mp4);
  if (!t)
    return file_error(mp4, 0, "no FBA track (a visual stream, objectTypeIndication 0x20, whose "
                              "configuration declares visual object type 4)");
  FbaTrackInput out;
  out.decoder_specific_info = t->es->config.specific_info;
  out.timescale = t->timescale;
  for (const Mp4Sample& s : t->samples) out.samples.push_back({mp4.sample_bytes(s), s.duration, s.sync});
  return out;
}

}  // namespace fapc::xmt

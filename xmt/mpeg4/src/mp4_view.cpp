// The project's view of an MP4 file: which track is the scene, the object descriptors, the FBA
// stream. Built on the generic reader; every "not found" names what was looked for.
#include "fapc/mpeg4/mp4_reader.hpp"

#include <algorithm>
#include <cstdint>

#include "fapc/mpeg4/codes.hpp"

namespace fapc::mpeg4 {

namespace {

const Mp4Track* find_stream(const Mp4File& mp4, std::uint8_t stream_type) {
  for (const Mp4Track& t : mp4.tracks)
    if (t.es && t.es->config.stream_type == stream_type) return &t;
  return nullptr;
}

// Edit durations past this (in any timescale, 2^40 ticks: over 34 years at 1000 per second) are
// read as this, so that converting them between timescales stays within 64 bits.
constexpr std::uint64_t kLongestEdit = std::uint64_t{1} << 40;

Diagnostic file_error(ErrorCode code, const Mp4File& mp4, std::uint64_t offset, const std::string& message) {
  return make_error(code, Location::binary(mp4.file, static_cast<std::int64_t>(offset)), message);
}

}  // namespace

Result<Mp4SceneView> read_scene(const Mp4File& mp4) {
  const Mp4Track* t = find_stream(mp4, kSceneDescriptionStream);
  if (!t) return file_error(codes::mp4::no_scene_track, mp4, 0, "no scene description track");
  const std::uint8_t oti = t->es->config.object_type;
  if (oti != 1 && oti != 2)
    return file_error(
        codes::mp4::scene_not_bifs, mp4, t->es_offset,
        "scene track " + std::to_string(t->id) + " is not BIFS (objectTypeIndication " + std::to_string(oti) + ")");
  if (t->samples.empty())
    return file_error(codes::mp4::empty_track, mp4, t->box_offset, "scene track has no access unit");
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
  if (!t) return file_error(codes::mp4::no_od_track, mp4, 0, "no object descriptor track");
  if (t->samples.empty())
    return file_error(codes::mp4::empty_track, mp4, t->box_offset, "object descriptor track has no access unit");
  const Mp4Sample& first = t->samples.front();
  auto ods = decode_object_descriptor_updates(mp4.sample_bytes(first), first.offset, mp4.file);
  if (!ods) return ods.error();
  std::vector<Mp4ObjectView> out;
  for (ObjectDescriptor& od : *ods) {
    Mp4ObjectView view;
    for (std::uint16_t ref : od.es_id_refs) {
      if (ref == 0 || ref > t->mpod.size())
        return file_error(codes::mp4::missing_stream, mp4, first.offset,
                          "object descriptor " + std::to_string(od.od_id) + " refers to stream " + std::to_string(ref) +
                              " of the OD track's " + std::to_string(t->mpod.size()) + " 'mpod' references");
      view.track_ids.push_back(t->mpod[ref - 1]);
    }
    view.od = std::move(od);
    out.push_back(std::move(view));
  }
  return out;
}

const Mp4Track* find_fba_track(const Mp4File& mp4) {
  for (const Mp4Track& t : mp4.tracks)
    if (t.es && t.es->config.stream_type == kVisualStream && t.es->config.object_type == kVisual14496_2Object &&
        declares_fba_object(t.es->config.specific_info))
      return &t;
  return nullptr;
}

Result<FbaTrackInput> read_fba_track(const Mp4File& mp4) {
  const Mp4Track* t = find_fba_track(mp4);
  if (!t)
    return file_error(codes::mp4::no_fba_track, mp4, 0,
                      "no FBA track (a visual stream, objectTypeIndication 0x20, whose "
                      "configuration declares visual object type 4)");
  FbaTrackInput out;
  out.decoder_specific_info = t->es->config.specific_info;
  out.timescale = t->timescale;
  for (const Mp4Sample& s : t->samples) out.samples.push_back({mp4.sample_bytes(s), s.duration, s.sync});
  return out;
}

const Mp4Track* find_audio_track(const Mp4File& mp4) {
  for (const Mp4Track& t : mp4.tracks)
    if (t.es && t.es->config.stream_type == kAudioStream && t.es->config.object_type == kAudio14496_3Object) return &t;
  return nullptr;
}

Result<AudioTrackInput> read_audio_track(const Mp4File& mp4, const Mp4Track& t) {
  const std::string id = "audio track " + std::to_string(t.id);
  if (!t.es) return file_error(codes::mp4::missing_descriptor, mp4, t.box_offset, id + " has no decoder configuration");
  if (t.samples.empty()) return file_error(codes::mp4::empty_track, mp4, t.box_offset, id + " has no access unit");
  AudioTrackInput out;
  out.decoder_specific_info = t.es->config.specific_info;
  out.sample_rate = t.timescale;
  out.channels = audio_channel_configuration(out.decoder_specific_info);
  out.samples_per_unit = t.samples.front().duration;
  out.config_offset = static_cast<std::int64_t>(t.es_offset);
  out.sample_offsets.reserve(t.samples.size());
  std::uint64_t media = 0;
  for (std::size_t i = 0; i < t.samples.size(); ++i) {
    const Mp4Sample& s = t.samples[i];
    // The last access unit may be shorter: some writers give it only the sound it holds.
    if (s.duration != out.samples_per_unit && i + 1 != t.samples.size())
      return file_error(codes::mp4::bad_sample_table, mp4, s.offset,
                        id + ": access unit " + std::to_string(i + 1) + " lasts " + std::to_string(s.duration) +
                            " ticks, the first " + std::to_string(out.samples_per_unit));
    out.samples.push_back(mp4.sample_bytes(s));
    out.sample_offsets.push_back(s.offset);
    media += s.duration;
  }
  // Without an edit list the whole media plays from time 0.
  out.media_start = 0;
  out.length = media;
  std::size_t i = 0;
  if (!t.edits.empty() && t.edits.front().media_time == -1) {
    // In milliseconds, the unit the writer takes; capped so the products below cannot overflow.
    const std::uint64_t ticks = std::min<std::uint64_t>(t.edits.front().duration, kLongestEdit);
    const std::uint64_t delay = mp4.timescale ? (ticks * 1000 + mp4.timescale / 2) / mp4.timescale : 0;
    out.delay_ms = static_cast<std::uint32_t>(std::min<std::uint64_t>(delay, UINT32_MAX));
    ++i;
  }
  if (i < t.edits.size()) {
    const Mp4Edit& sound = t.edits[i];
    if (i + 1 < t.edits.size())
      return file_error(codes::mp4::edit_list_not_read, mp4, t.edits_offset,
                        id + ": an edit list of more than one stretch of sound is not read by fapc");
    if (sound.media_time < 0 || static_cast<std::uint64_t>(sound.media_time) > media)
      return file_error(codes::mp4::edit_list_not_read, mp4, t.edits_offset,
                        id + ": the edit list starts the sound at tick " + std::to_string(sound.media_time) + " of " +
                            std::to_string(media));
    out.media_start = static_cast<std::uint64_t>(sound.media_time);
    // The edit's length is in the movie's timescale: back to samples, never past the media.
    const std::uint64_t ticks = std::min<std::uint64_t>(sound.duration, kLongestEdit);
    const std::uint64_t length = mp4.timescale ? (ticks * t.timescale + mp4.timescale / 2) / mp4.timescale : 0;
    out.length = std::min(length, media - out.media_start);
  } else {
    out.length = media;
  }
  if (out.length == 0)
    return file_error(codes::mp4::edit_list_not_read, mp4, t.edits_offset, id + ": the edit list leaves no sound");
  return out;
}

}  // namespace fapc::mpeg4

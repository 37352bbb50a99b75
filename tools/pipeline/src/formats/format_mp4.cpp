// .mp4 in and out: an MPEG-4 file with a BIFS face scene, an OD track and the FBA track
// (docs/mp4-and-xmta.md). The container work is the xmt library's; the FBA coding is the
// codec's.
#include <filesystem>
#include <sstream>

#include "../audio_io.hpp"
#include "../fba_frame_writer.hpp"
#include "../verify_streams.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

namespace {

std::string hex_byte(unsigned v) {
  std::ostringstream s;
  s << "0x" << std::uppercase << std::hex << (v < 16 ? "0" : "") << v;
  return s.str();
}

std::string track_line(const mpeg4::Mp4Track& t, const mpeg4::Mp4Track* fba) {
  std::ostringstream s;
  s << t.handler << ' ' << t.sample_entry;
  if (t.es) {
    const mpeg4::DecoderConfig& c = t.es->config;
    const char* role = &t == fba                                         ? "FBA stream"
                       : c.stream_type == mpeg4::kSceneDescriptionStream ? "scene description"
                       : c.stream_type == mpeg4::kObjectDescriptorStream ? "object_descriptors"
                       : c.stream_type == mpeg4::kAudioStream            ? "audio"
                                                                         : "stream";
    s << ", " << role << " (streamType " << int{c.stream_type} << ", objectTypeIndication " << hex_byte(c.object_type)
      << ")";
  }
  std::size_t sync = 0;
  for (const mpeg4::Mp4Sample& sample : t.samples) sync += sample.sync ? 1 : 0;
  s << ", " << t.samples.size() << (t.samples.size() == 1 ? " sample (" : " samples (") << sync << " sync), timescale "
    << t.timescale;
  return s.str();
}

std::string profiles_text(const mpeg4::ProfileLevels& p) {
  std::string visual = hex_byte(p.visual);
  if (const auto name = mpeg4::fba_profile_name(p.visual); !name.empty()) visual += " " + std::string(name);
  return "OD " + hex_byte(p.od) + ", scene " + hex_byte(p.scene) + ", audio " + hex_byte(p.audio) + ", visual " +
         visual + ", graphics " + hex_byte(p.graphics);
}

nlohmann::ordered_json facts_of(const mpeg4::Mp4File* mp4) {
  nlohmann::ordered_json out;
  out["major_brand"] = mp4->major_brand;
  out["compatible_brands"] = mp4->compatible_brands;
  out["movie_duration"] = mp4->timescale ? static_cast<double>(mp4->duration) / mp4->timescale : 0.0;
  if (mp4->iod) out["profile_levels"] = profiles_text(mp4->iod->profiles);
  const mpeg4::Mp4Track* fba = mpeg4::find_fba_track(*mp4);
  nlohmann::ordered_json tracks = nlohmann::ordered_json::array();
  for (const mpeg4::Mp4Track& t : mp4->tracks) tracks.push_back({{"id", t.id}, {"description", track_line(t, fba)}});
  out["tracks"] = tracks;
  // A scene or descriptors outside what fapc decodes are shown as the reason, not as a failure.
  auto scene = mpeg4::read_scene(*mp4);
  out["scene"] = scene ? mpeg4::scene_text(scene->scene) : "not shown: " + format_diagnostic(scene.error());
  auto objects = mpeg4::read_object_descriptors(*mp4);
  nlohmann::ordered_json ods = nlohmann::ordered_json::array();
  if (objects) {
    for (const mpeg4::Mp4ObjectView& o : *objects) {
      std::string line = "OD " + std::to_string(o.od.od_id) + " ->";
      for (std::uint32_t id : o.track_ids) line += " track " + std::to_string(id);
      ods.push_back(line);
    }
    out["object_descriptors"] = ods;
  } else {
    out["object_descriptors"] = "not shown: " + format_diagnostic(objects.error());
  }
  if (auto stream = mpeg4::read_fba_track(*mp4)) {
    const std::uint8_t level = *mpeg4::fba_profile_level(stream->decoder_specific_info);
    std::uint64_t bytes = 0, ticks = 0;
    std::size_t intra = 0;
    for (const mpeg4::FbaSample& s : stream->samples) {
      bytes += s.bytes.size();
      ticks += s.duration;
      intra += s.sync ? 1 : 0;
    }
    out["fba_profile_level"] = hex_byte(level) + " " + std::string(mpeg4::fba_profile_name(level));
    out["fba_planes"] = stream->samples.size();
    out["fba_intra_planes"] = intra;
    out["fba_bytes"] = bytes;
    out["fba_duration"] = static_cast<double>(ticks) / stream->timescale;
  }
  if (const mpeg4::Mp4Track* voice = mpeg4::find_audio_track(*mp4)) {
    if (auto audio = mpeg4::read_audio_track(*mp4, *voice)) {
      const int type = mpeg4::audio_object_type(audio->decoder_specific_info);
      out["audio_codec"] = type == 2 ? "AAC-LC (mp4a.40.2)" : "MPEG-4 audio object type " + std::to_string(type);
      out["audio_sample_rate"] = audio->sample_rate;
      out["audio_channels"] = audio->channels;
      out["audio_duration"] = static_cast<double>(audio->length) / audio->sample_rate;
      out["audio_start"] = audio->delay_ms / 1000.0;
    } else {
      out["audio_codec"] = "not shown: " + format_diagnostic(audio.error());
    }
  }
  return out;
}

Result<Loaded> load_mp4(const std::string& path, const ConvertOptions& options) {
  auto bytes = read_file_bytes(path, options.limits);
  if (!bytes) return bytes.error();
  auto mp4 = mpeg4::read_mp4(mpeg4::Bytes(bytes->begin(), bytes->end()), path);
  if (!mp4) return mp4.error();
  auto fba = decode_mp4_fba(*mp4, path, options.limits);
  if (!fba) return fba.error();
  Loaded loaded;
  loaded.frames = std::move(fba->decoded.sequence);
  loaded.frames.name = std::filesystem::path(path).stem().string();
  loaded.warnings = std::move(fba->decoded.warnings);
  if (const mpeg4::Mp4Track* voice = mpeg4::find_audio_track(*mp4)) {
    auto track = mpeg4::read_audio_track(*mp4, *voice);
    if (!track) return track.error();
    auto audio = unpack_audio_track(*track, path, options.limits);
    if (!audio) return audio.error();
    loaded.audio = std::move(*audio);
  }
  if (options.facts) loaded.facts = json_value(facts_of(&*mp4));
  return loaded;
}

// The FBA track: the encoder's planes, each started by its start code and byte-aligned, become
// the samples.
Result<std::string> write_mp4_file(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  // An empty input would make a track without samples: say so about the input.
  if (loaded.frames.frames.empty())
    return make_error(codes::output::no_frames, Location::whole_file(loaded.named(path)),
                      "no frames to write: an MP4 FBA track needs at least one");
  auto encoded = encode_checked(loaded, options, loaded.named(path), /*align_planes=*/true);
  if (!encoded) return encoded.error();
  std::optional<mpeg4::AudioTrackInput> voice;
  if (loaded.audio) {
    auto packed = pack_audio_track(*loaded.audio, loaded.frames.duration_seconds(), loaded.named(path), options.limits);
    if (!packed) return packed.error();
    voice = std::move(*packed);
  }
  // The samples are views into the coded stream, the file made once: no copy of each plane.
  std::string bytes;
  const Status written = mpeg4::write_mp4(fba_track_view(*encoded, loaded.frames.fps), voice ? &*voice : nullptr,
                                          [&](std::span<const std::uint8_t> piece) {
                                            bytes.append(reinterpret_cast<const char*>(piece.data()), piece.size());
                                            return ok_status();
                                          });
  if (!written) {
    Diagnostic error = written.error();
    if (error.where.file.empty()) error.where.file = loaded.named(path);
    return error;
  }
  return bytes;
}

// Streamed (frames without a voice): the aligned encoding, then the file through a temporary
// one, in pieces, with the bytes of write_mp4_file.
class Mp4FrameWriter : public FbaFrameWriter {
 public:
  Mp4FrameWriter(const std::string& path, const std::string& input, const ConvertOptions& options, FrameSource& source)
      : FbaFrameWriter(path, input, options, source, /*align_planes=*/true) {}

  Status commit() override {
    // As write_mp4_file: an empty input would make a track without samples.
    if (facts_.frames == 0)
      return make_error(codes::output::no_frames, Location::whole_file(input_),
                        "no frames to write: an MP4 FBA track needs at least one");
    if (error_) return *error_;
    auto file = AtomicFile::create(path_);
    if (!file) return file.error();
    const Status written =
        mpeg4::write_mp4(fba_track_view(*encoded_, facts_.fps), nullptr, [&](std::span<const std::uint8_t> bytes) {
          return file->write({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
        });
    if (!written) {
      Diagnostic error = written.error();
      if (error.where.file.empty()) error.where.file = input_;
      return error;
    }
    return file->commit();
  }
};

}  // namespace

InputFormat mp4_input() {
  InputFormat format{"mp4", {".mp4"}, load_mp4};
  format.verify_stream = verify_mp4_file;
  return format;
}

OutputFormat mp4_output() {
  OutputFormat format{"mp4", {".mp4"}, write_mp4_file};
  format.uses_audio = true;
  format.frame_writer = [](const std::string& path, const std::string& input, const ConvertOptions& options,
                           FrameSource& source) {
    return std::unique_ptr<FrameWriter>(std::make_unique<Mp4FrameWriter>(path, input, options, source));
  };
  return format;
}

}  // namespace fapc::pipeline::builtin

#include "audio_io.hpp"

#include <cmath>

#include "fapc/audio_codec/aac.hpp"

namespace fapc::pipeline {

Result<std::optional<mpeg4::AudioTrackInput>> pack_audio_track(const AudioTrack& audio, double face_seconds,
                                                               const std::string& where, const Limits& limits) {
  if (audio.samples.empty() || audio.sample_rate <= 0) return std::optional<mpeg4::AudioTrackInput>{};
  // The track lasts as long as the face: silence after the voice is coded, never stored.
  std::size_t length = audio.samples.size();
  const double face_end = std::round((face_seconds - audio.start) * audio.sample_rate);
  if (face_end > static_cast<double>(limits.max_audio_samples))
    return limit_error(Location::whole_file(where),
                       "the voice track would run to the face's end, " +
                           std::to_string(static_cast<std::int64_t>(face_end)) + " samples at " +
                           std::to_string(audio.sample_rate) + " Hz",
                       Limit::audio_samples, limits);
  if (face_end > static_cast<double>(length)) length = static_cast<std::size_t>(std::llround(face_end));
  // Sound before the face's time 0 has nowhere to play: it is cut (the edit list skips it).
  const double rate = audio.sample_rate;
  const auto skip = audio.start < 0 ? static_cast<std::uint64_t>(std::llround(-audio.start * rate)) : 0;
  if (skip >= length) return std::optional<mpeg4::AudioTrackInput>{};
  auto aac = audio_codec::encode_aac(audio, where, 64000, length);
  if (!aac) return aac.error();
  mpeg4::AudioTrackInput track;
  track.decoder_specific_info = std::move(aac->audio_specific_config);
  track.sample_rate = static_cast<std::uint32_t>(aac->sample_rate);
  track.channels = aac->channels;
  track.samples = std::move(aac->frames);
  track.samples_per_unit = audio_codec::kAacFrameLength;
  track.media_start = aac->priming + skip;
  track.length = aac->length - skip;
  track.delay_ms = audio.start > 0 ? static_cast<std::uint32_t>(std::llround(audio.start * 1000)) : 0;
  return std::optional<mpeg4::AudioTrackInput>(std::move(track));
}

Result<AudioTrack> unpack_audio_track(const mpeg4::AudioTrackInput& track, const std::string& where,
                                      const Limits& limits) {
  const Location at = Location::whole_file(where);
  if (static_cast<double>(track.length) > static_cast<double>(limits.max_audio_samples))
    return limit_error(at, "the audio track holds " + std::to_string(track.length) + " samples", Limit::audio_samples,
                       limits);
  if (static_cast<double>(track.length) * 2 > static_cast<double>(limits.max_decompressed_bytes))
    return limit_error(at, "the audio track decodes to " + std::to_string(track.length * 2) + " bytes",
                       Limit::decompressed_bytes, limits);
  audio_codec::AacStream stream;
  stream.sample_rate = static_cast<int>(track.sample_rate);
  stream.channels = std::max(1, track.channels);
  stream.audio_specific_config = track.decoder_specific_info;
  stream.frames = track.samples;
  stream.priming = track.media_start;
  stream.length = track.length;
  stream.config_offset = track.config_offset;
  stream.frame_offsets = track.sample_offsets;
  auto samples = audio_codec::decode_aac(stream, where);
  if (!samples) return samples.error();
  AudioTrack out;
  out.sample_rate = static_cast<int>(track.sample_rate);
  out.start = track.delay_ms / 1000.0;
  out.samples = std::move(*samples);
  return out;
}

}  // namespace fapc::pipeline

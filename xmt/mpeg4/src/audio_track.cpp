#include "fapc/mpeg4/audio_track.hpp"

#include <array>
#include <string>

#include "fapc/mpeg4/codes.hpp"

namespace fapc::mpeg4 {

namespace {

constexpr std::array<std::uint32_t, 13> kFrequencies = {96000, 88200, 64000, 48000, 44100, 32000, 24000,
                                                        22050, 16000, 12000, 11025, 8000,  7350};

// The first 40 bits of an AudioSpecificConfig, big-endian, zero past the end.
std::uint64_t head_bits(const Bytes& c) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < 5; ++i) v = (v << 8) | (i < c.size() ? c[i] : 0U);
  return v;
}
std::uint32_t bits_at(std::uint64_t head, int first, int count) {
  return static_cast<std::uint32_t>((head >> (40 - first - count)) & ((std::uint64_t{1} << count) - 1));
}

}  // namespace

int audio_object_type(const Bytes& c) {
  if (c.size() < 2) return 0;
  const std::uint32_t type = bits_at(head_bits(c), 0, 5);
  return static_cast<int>(type == 31 ? 32 + bits_at(head_bits(c), 5, 6) : type);
}

// Only the 5-bit object types are followed further (an escaped type shifts every later field).
std::uint32_t audio_sample_rate(const Bytes& c) {
  if (c.size() < 2 || bits_at(head_bits(c), 0, 5) == 31) return 0;
  const std::uint32_t index = bits_at(head_bits(c), 5, 4);
  if (index == 15) return c.size() >= 5 ? bits_at(head_bits(c), 9, 24) : 0;
  return index < kFrequencies.size() ? kFrequencies[index] : 0;
}

int audio_channel_configuration(const Bytes& c) {
  if (c.size() < 2 || bits_at(head_bits(c), 0, 5) == 31) return 0;
  const int first = bits_at(head_bits(c), 5, 4) == 15 ? 33 : 9;
  if (static_cast<std::size_t>(first + 4) > c.size() * 8) return 0;
  return static_cast<int>(bits_at(head_bits(c), first, 4));
}

std::uint8_t aac_profile_level(std::uint32_t sample_rate) { return sample_rate <= 24000 ? 0x28 : 0x29; }

Status check_audio_track(const AudioTrackInput& t) {
  const Location nowhere{};
  if (t.decoder_specific_info.empty())
    return make_error(codes::mp4::bad_audio_track, nowhere, "audio track without a decoder configuration");
  if (t.sample_rate == 0)
    return make_error(codes::mp4::bad_audio_track, nowhere, "audio track with a sample rate of 0");
  if (t.samples.empty()) return make_error(codes::mp4::bad_audio_track, nowhere, "audio track without access units");
  if (t.samples_per_unit == 0)
    return make_error(codes::mp4::bad_audio_track, nowhere, "audio access units of 0 samples");
  if (t.length == 0) return make_error(codes::mp4::bad_audio_track, nowhere, "audio track without sound (length 0)");
  // A version 0 edit list holds the media time in 32 signed bits.
  if (t.media_start > 0x7FFFFFFF)
    return make_error(codes::mp4::bad_audio_track, nowhere,
                      "audio track: the sound starts " + std::to_string(t.media_start) +
                          " samples into its media, more than an edit list says");
  const std::uint64_t media = t.samples.size() * std::uint64_t{t.samples_per_unit};
  if (t.media_start + t.length > media)
    return make_error(codes::mp4::bad_audio_track, nowhere,
                      "audio track: " + std::to_string(t.media_start + t.length) +
                          " samples of sound in access units holding " + std::to_string(media));
  return ok_status();
}

}  // namespace fapc::mpeg4

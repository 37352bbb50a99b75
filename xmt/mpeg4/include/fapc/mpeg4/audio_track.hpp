// An MPEG-4 audio elementary stream as the MP4 writer takes it and the reader gives it back:
// the decoder configuration (AudioSpecificConfig) and the coded access units, placed on the
// face's clock. Nothing here codes audio; fapc::audio_codec does (docs/mp4-and-xmta.md 1.2).
#pragma once

#include <cstdint>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/mpeg4/fba_track.hpp"

namespace fapc::xmt {

inline constexpr std::uint8_t kAudioStream = 0x05;         // streamType
inline constexpr std::uint8_t kAudio14496_3Object = 0x40;  // objectTypeIndication: MPEG-4 audio

struct AudioTrackInput {
  Bytes decoder_specific_info;    // AudioSpecificConfig
  std::uint32_t sample_rate = 0;  // the track's timescale
  int channels = 1;
  std::vector<Bytes> samples;             // one access unit each
  std::uint32_t samples_per_unit = 1024;  // every access unit's duration, in samples
  // Where the sound starts in the media (samples to skip: the encoder's priming) and how many
  // samples are sound. The edit list says both.
  std::uint64_t media_start = 0;
  std::uint64_t length = 0;
  // Where it starts on the face's clock, in the movie's timescale (1000: milliseconds): an empty
  // edit of that length comes first. (Sound that starts before the face is cut at the face's
  // start by raising media_start.)
  std::uint32_t delay_ms = 0;
  // Where a track read from a file came from, for errors found later (the AAC decoder's): the
  // file offset of its ES_Descriptor and of each access unit. Empty (-1) for a track made, not
  // read. Not part of the sound: == leaves them out.
  std::int64_t config_offset = -1;
  std::vector<std::uint64_t> sample_offsets;
  friend bool operator==(const AudioTrackInput& a, const AudioTrackInput& b) {
    return a.decoder_specific_info == b.decoder_specific_info && a.sample_rate == b.sample_rate &&
           a.channels == b.channels && a.samples == b.samples && a.samples_per_unit == b.samples_per_unit &&
           a.media_start == b.media_start && a.length == b.length && a.delay_ms == b.delay_ms;
  }
};

// What the writer relies on: a configuration, at least one access unit, a positive rate, the
// sound inside the access units. The error says which.
Status check_audio_track(const AudioTrackInput& track);

// The audio object type of an AudioSpecificConfig (2 = AAC-LC), 0 when it is too short.
int audio_object_type(const Bytes& audio_specific_config);
// Its channelConfiguration, 0 when not given in the first bytes.
int audio_channel_configuration(const Bytes& audio_specific_config);
// Its sampling frequency in Hz (from the index or the 24-bit escape), 0 when not given.
std::uint32_t audio_sample_rate(const Bytes& audio_specific_config);

// The initial object descriptor's audioProfileLevelIndication for AAC-LC: AAC Profile @ L1 (0x28)
// up to 24 kHz and two channels, @ L2 (0x29) above (the levels of 14496-3's AAC Profile).
std::uint8_t aac_profile_level(std::uint32_t sample_rate);

}  // namespace fapc::xmt

// libFuzzer target: the audio track of an .mp4 (its boxes: stsd/esds configuration, stts/stsz/
// stco samples, the edit list) read and decoded. Edit lists of a day or of the largest duration
// (issue 32) must give a delay, never an allocation; an accepted track's length is bounded by
// its samples, and an error of the reader carries the byte offset of its box or sample.
#include <cstdint>
#include <cstdlib>

#include "fapc/audio_codec/aac.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapc::mpeg4;
  auto mp4 = read_mp4(Bytes(data, data + size), "fuzz.mp4");
  if (!mp4.ok()) return 0;
  const Mp4Track* found = find_audio_track(*mp4);
  if (found == nullptr) return 0;
  auto track = read_audio_track(*mp4, *found);
  if (!track.ok()) {
    if (track.error().where.byte_offset < 0) std::abort();
    return 0;
  }
  // The media holds at most its access units' ticks; the length never passes them.
  if (track->media_start + track->length < track->length) std::abort();
  if (track->length > (std::uint64_t{1} << 22)) return 0;  // decoding is bounded by the caller's limit
  fapc::audio_codec::AacStream stream;
  stream.sample_rate = static_cast<int>(track->sample_rate);
  stream.channels = track->channels < 1 ? 1 : track->channels;
  stream.audio_specific_config = track->decoder_specific_info;
  stream.frames = track->samples;
  stream.priming = track->media_start;
  stream.length = track->length;
  stream.config_offset = track->config_offset;
  stream.frame_offsets = track->sample_offsets;
  auto samples = fapc::audio_codec::decode_aac(stream, "fuzz.mp4");
  if (samples.ok() && samples->size() != track->length) std::abort();
  // The decoder's errors name the configuration or the access unit (issue 32).
  if (!samples.ok() && samples.error().where.byte_offset < 0) std::abort();
  return 0;
}

// Speech audio as AAC-LC (ISO/IEC 14496-3) access units, the form an MP4 audio track carries,
// coded through libavcodec. Mono only: fapc's audio (AudioTrack) is one channel.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/timeline/audio.hpp"

namespace fapc::audio_codec {

inline constexpr int kAacFrameLength = 1024;  // samples per AAC-LC access unit (frameLengthFlag 0)

struct AacStream {
  int sample_rate = 0;
  int channels = 1;
  std::vector<std::uint8_t> audio_specific_config;  // the decoder specific info (14496-3 §1.6.2.1)
  std::vector<std::vector<std::uint8_t>> frames;    // raw access units, kAacFrameLength samples each
  // The encoder's delay: decoded output begins with this many samples that are not the input.
  std::uint64_t priming = 0;
  std::uint64_t length = 0;  // samples of the input, after the priming
  // Where a stream read from a file came from (decode_aac's errors name these byte offsets): its
  // configuration and each access unit. -1 or empty: errors name the whole file.
  std::int64_t config_offset = -1;
  std::vector<std::uint64_t> frame_offsets;
};

// AAC-LC sampling frequency indexes (ISO/IEC 14496-3's samplingFrequencyIndex), or -1 for a rate
// AAC has no index for.
int aac_frequency_index(int sample_rate);

// The AudioSpecificConfig of mono AAC-LC at `sample_rate`, written from the standard's syntax
// (14496-3 §1.6.2.1, not taken from libavcodec): audioObjectType 2 (5 bits),
// samplingFrequencyIndex (4), channelConfiguration 1 (4), GASpecificConfig frameLengthFlag 0,
// dependsOnCoreCoder 0, extensionFlag 0; then the backward-compatible explicit signalling that
// there is no SBR: syncExtensionType 0x2B7 (11 bits), extensionAudioObjectType 5 (5),
// sbrPresentFlag 0 (1), zero padding. Five bytes (0x13 0x88 0x56 0xE5 0x00 at 22050 Hz), the same that
// libavcodec's encoder announces. Without the extension a decoder may assume implicit SBR at
// rates up to 24 kHz (HE-AAC, output at twice the rate). Empty for a rate without an index.
std::vector<std::uint8_t> aac_lc_mono_config(int sample_rate);

// libavcodec's AAC encoders ("aac_coder"): `twoloop`, its default, searches the quantisers of
// every band in two nested loops; `fast` takes them from the band's energy in one pass. For the
// speech fapc makes (one voice, 22050 Hz mono at 64 kbit/s) fast is about 3 times quicker with
// the same loudness and timing (bench/batch_bench.cpp measures both), so it is fapc's default.
enum class AacCoder { fast, twoloop };

// Encodes the track at its own rate (which must have an AAC frequency index: 8000 to 96000 Hz
// standard rates, else unsupported, placed at the track's source when it has one: the clip that
// set the rate) at `bit_rate` bits per second. `where` names the output.
// `length` > track.samples.size() continues the track with that many samples in all, the rest
// silence that is never stored (the voice of a face that keeps moving after it).
Result<AacStream> encode_aac(const AudioTrack& track, const std::string& where, int bit_rate = 64000,
                             std::size_t length = 0, AacCoder coder = AacCoder::fast);

// Decodes the access units back to mono samples, the priming dropped and the result cut to
// `stream.length` (decoders of lossy audio give close, not equal, samples). `where` names the file;
// errors carry the byte offset of the configuration or access unit at fault when the stream has them.
Result<std::vector<std::int16_t>> decode_aac(const AacStream& stream, const std::string& where);

}  // namespace fapc::audio_codec

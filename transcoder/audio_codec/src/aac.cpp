#include "fapc/audio_codec/aac.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavutil/channel_layout.h>
#include <libavutil/dict.h>
#include <libavutil/log.h>
}

#include <algorithm>
#include <array>
#include <cmath>

#include "fapc/audio_codec/codes.hpp"

namespace fapc::audio_codec {

namespace {

std::string av_message(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// Owners for the libav objects, so every error path frees them.
struct Coder {
  AVCodecContext* context = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  ~Coder() {
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&context);
  }
};

constexpr std::array<int, 13> kFrequencies = {96000, 88200, 64000, 48000, 44100, 32000, 24000,
                                              22050, 16000, 12000, 11025, 8000,  7350};

}  // namespace

int aac_frequency_index(int sample_rate) {
  for (std::size_t i = 0; i < kFrequencies.size(); ++i)
    if (kFrequencies[i] == sample_rate) return static_cast<int>(i);
  return -1;
}

std::vector<std::uint8_t> aac_lc_mono_config(int sample_rate) {
  const int index = aac_frequency_index(sample_rate);
  if (index < 0) return {};
  constexpr std::uint64_t kAacLc = 2, kMono = 1, kSyncExtension = 0x2B7, kSbr = 5;
  // 5 bits object type, 4 frequency index, 4 channels, 3 zero GASpecificConfig bits; 11 bits
  // sync extension, 5 extension object type, 1 sbrPresentFlag (0): 33 bits in 40.
  const std::uint64_t bits =
      (kAacLc << 35) | (static_cast<std::uint64_t>(index) << 31) | (kMono << 27) | (kSyncExtension << 13) | (kSbr << 8);
  std::vector<std::uint8_t> out;
  for (int shift = 32; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>((bits >> shift) & 0xFF));
  return out;
}

Result<AacStream> encode_aac(const AudioTrack& track, const std::string& where, int bit_rate, std::size_t length,
                             AacCoder coder) {
  const Location at = Location::whole_file(where);
  if (aac_frequency_index(track.sample_rate) < 0)
    return make_error(codes::aac::sample_rate, track.source.file.empty() ? at : track.source,
                      "audio at " + std::to_string(track.sample_rate) +
                          " Hz: AAC takes 7350, 8000, 11025, 12000, 16000, 22050, 24000, 32000, 44100, "
                          "48000, 64000, 88200 or 96000 Hz");
  auto failed = [&](const std::string& what, int code) {
    return make_error(codes::aac::encoder_failed, at, what + ": " + av_message(code));
  };
  av_log_set_level(AV_LOG_QUIET);  // a library does not print; errors come back as codes
  const AVCodec* aac = avcodec_find_encoder(AV_CODEC_ID_AAC);
  if (!aac) return make_error(codes::aac::no_codec, at, "this libavcodec has no AAC encoder");
  Coder c;
  c.context = avcodec_alloc_context3(aac);
  c.context->sample_rate = track.sample_rate;
  c.context->sample_fmt = AV_SAMPLE_FMT_FLTP;
  av_channel_layout_default(&c.context->ch_layout, 1);
  c.context->bit_rate = bit_rate;
  c.context->profile = FF_PROFILE_AAC_LOW;
  c.context->time_base = AVRational{1, track.sample_rate};
  c.context->flags |= AV_CODEC_FLAG_GLOBAL_HEADER | AV_CODEC_FLAG_BITEXACT;
  c.context->thread_count = 1;
  AVDictionary* settings = nullptr;
  av_dict_set(&settings, "aac_coder", coder == AacCoder::fast ? "fast" : "twoloop", 0);
  const int opened = avcodec_open2(c.context, aac, &settings);
  av_dict_free(&settings);
  if (opened < 0) return failed("cannot open the AAC encoder", opened);

  AacStream out;
  out.sample_rate = track.sample_rate;
  out.priming = static_cast<std::uint64_t>(std::max(0, c.context->initial_padding));
  out.length = std::max(length, track.samples.size());
  out.audio_specific_config = aac_lc_mono_config(track.sample_rate);
  const std::vector<std::uint8_t> given(c.context->extradata, c.context->extradata + c.context->extradata_size);
  if (given != out.audio_specific_config)
    return make_error(codes::aac::encoder_unexpected, at,
                      "libavcodec's AAC encoder announced a configuration other than mono AAC-LC");
  const int frame_size = c.context->frame_size > 0 ? c.context->frame_size : kAacFrameLength;
  if (frame_size != kAacFrameLength)
    return make_error(codes::aac::encoder_unexpected, at,
                      "libavcodec's AAC encoder uses " + std::to_string(frame_size) + "-sample frames");

  c.frame = av_frame_alloc();
  c.frame->format = AV_SAMPLE_FMT_FLTP;
  c.frame->nb_samples = frame_size;
  c.frame->sample_rate = track.sample_rate;
  av_channel_layout_default(&c.frame->ch_layout, 1);
  if (int e = av_frame_get_buffer(c.frame, 0); e < 0) return failed("cannot allocate an audio frame", e);
  c.packet = av_packet_alloc();
  auto drain = [&]() -> int {
    for (;;) {
      const int e = avcodec_receive_packet(c.context, c.packet);
      if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return 0;
      if (e < 0) return e;
      out.frames.emplace_back(c.packet->data, c.packet->data + c.packet->size);
      av_packet_unref(c.packet);
    }
  };
  // Whole frames only; the last is padded with silence (the file's edit list cuts it off).
  const std::size_t n = track.samples.size();
  for (std::size_t first = 0; first < out.length; first += static_cast<std::size_t>(frame_size)) {
    if (int e = av_frame_make_writable(c.frame); e < 0) return failed("cannot reuse an audio frame", e);
    auto* data = reinterpret_cast<float*>(c.frame->data[0]);
    for (int i = 0; i < frame_size; ++i) {
      const std::size_t k = first + static_cast<std::size_t>(i);
      data[i] = k < n ? static_cast<float>(track.samples[k]) / 32768.0F : 0.0F;
    }
    c.frame->pts = static_cast<std::int64_t>(first);
    if (int e = avcodec_send_frame(c.context, c.frame); e < 0) return failed("AAC encoding failed", e);
    if (int e = drain(); e < 0) return failed("AAC encoding failed", e);
  }
  if (int e = avcodec_send_frame(c.context, nullptr); e < 0) return failed("AAC encoding failed", e);
  if (int e = drain(); e < 0) return failed("AAC encoding failed", e);
  if (out.frames.size() * kAacFrameLength < out.priming + out.length)
    return make_error(codes::aac::encoder_failed, at, "the AAC encoder gave fewer frames than the audio needs");
  return out;
}

Result<std::vector<std::int16_t>> decode_aac(const AacStream& stream, const std::string& where) {
  const Location at = Location::whole_file(where);
  const Location config_at = stream.config_offset >= 0 ? Location::binary(where, stream.config_offset) : at;
  // Access unit i (from 0), or the last one for an error at the stream's end.
  auto unit_at = [&](std::size_t i) {
    if (stream.frame_offsets.empty()) return at;
    return Location::binary(
        where, static_cast<std::int64_t>(stream.frame_offsets[std::min(i, stream.frame_offsets.size() - 1)]));
  };
  auto failed_at = [](const Location& place, const std::string& what, int code) {
    return make_error(codes::aac::does_not_decode, place, what + ": " + av_message(code));
  };
  av_log_set_level(AV_LOG_QUIET);
  const AVCodec* aac = avcodec_find_decoder(AV_CODEC_ID_AAC);
  if (!aac) return make_error(codes::aac::no_codec, at, "this libavcodec has no AAC decoder");
  Coder c;
  c.context = avcodec_alloc_context3(aac);
  c.context->sample_rate = stream.sample_rate;
  av_channel_layout_default(&c.context->ch_layout, stream.channels);
  c.context->extradata =
      static_cast<std::uint8_t*>(av_mallocz(stream.audio_specific_config.size() + AV_INPUT_BUFFER_PADDING_SIZE));
  std::copy(stream.audio_specific_config.begin(), stream.audio_specific_config.end(), c.context->extradata);
  c.context->extradata_size = static_cast<int>(stream.audio_specific_config.size());
  c.context->thread_count = 1;
  if (int e = avcodec_open2(c.context, aac, nullptr); e < 0)
    return failed_at(config_at, "cannot open the AAC decoder for this configuration", e);
  c.frame = av_frame_alloc();
  c.packet = av_packet_alloc();

  std::vector<std::int16_t> samples;
  std::uint64_t skip = stream.priming;
  const std::uint64_t want = stream.length;
  auto take = [&]() -> int {
    for (;;) {
      const int e = avcodec_receive_frame(c.context, c.frame);
      if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return 0;
      if (e < 0) return e;
      // The first channel; planar float is what libavcodec's AAC decoder gives.
      if (c.frame->format != AV_SAMPLE_FMT_FLTP) return AVERROR(EINVAL);
      const auto* data = reinterpret_cast<const float*>(c.frame->data[0]);
      for (int i = 0; i < c.frame->nb_samples && samples.size() < want; ++i) {
        if (skip > 0) {
          --skip;
          continue;
        }
        const float v = std::clamp(data[i], -1.0F, 32767.0F / 32768.0F);
        samples.push_back(static_cast<std::int16_t>(std::lround(v * 32768.0F)));
      }
      av_frame_unref(c.frame);
    }
  };
  for (std::size_t i = 0; i < stream.frames.size() && samples.size() < want; ++i) {
    const auto& frame = stream.frames[i];
    if (int e = av_new_packet(c.packet, static_cast<int>(frame.size())); e < 0)
      return failed_at(unit_at(i), "cannot allocate an AAC packet", e);
    std::copy(frame.begin(), frame.end(), c.packet->data);
    const int e = avcodec_send_packet(c.context, c.packet);
    av_packet_unref(c.packet);
    if (e < 0) return failed_at(unit_at(i), "AAC access unit " + std::to_string(i + 1) + " does not decode", e);
    if (int t = take(); t < 0)
      return failed_at(unit_at(i), "AAC access unit " + std::to_string(i + 1) + " does not decode", t);
  }
  const std::size_t last = stream.frames.empty() ? 0 : stream.frames.size() - 1;
  if (samples.size() < want) {
    avcodec_send_packet(c.context, nullptr);
    if (int t = take(); t < 0) return failed_at(unit_at(last), "the AAC stream's end does not decode", t);
  }
  if (samples.size() < want)
    return make_error(codes::aac::truncated, unit_at(last),
                      "the AAC track decodes to " + std::to_string(samples.size()) + " samples; its edit list says " +
                          std::to_string(want));
  return samples;
}

}  // namespace fapc::audio_codec

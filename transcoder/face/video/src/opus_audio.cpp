#include "opus_audio.hpp"

#include "av_error.hpp"

extern "C" {
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
#include <libswresample/swresample.h>
}

#include <algorithm>
#include <cmath>

#include "fapc/face/codes.hpp"

namespace fapc::face {

namespace {

struct Resampler {
  SwrContext* swr = nullptr;
  ~Resampler() { swr_free(&swr); }
};

struct FrameOwner {
  AVFrame* frame = nullptr;
  ~FrameOwner() { av_frame_free(&frame); }
};

}  // namespace

OpusPackets::~OpusPackets() {
  for (AVPacket*& p : packets) av_packet_free(&p);
  avcodec_free_context(&codec);
}

Result<std::unique_ptr<OpusPackets>> encode_opus(const AudioInput& audio, bool global_header, const Location& at) {
  auto failed = [&](const std::string& what, int code) {
    return make_error(codes::video::encoder_failed, at, what + ": " + av_message(code));
  };
  if (audio.sample_rate <= 0 || audio.channels < 1 || audio.channels > 2)
    return make_error(codes::video::audio_layout, at, "audio for a .webm must be mono or stereo at a positive rate");
  const AVCodec* opus = avcodec_find_encoder_by_name("libopus");
  if (!opus) return make_error(codes::video::no_codec, at, "this libavcodec has no libopus encoder");
  auto out = std::make_unique<OpusPackets>();
  out->codec = avcodec_alloc_context3(opus);
  AVCodecContext* c = out->codec;
  c->sample_rate = kOpusRate;
  c->sample_fmt = AV_SAMPLE_FMT_FLT;
  av_channel_layout_default(&c->ch_layout, audio.channels);
  c->bit_rate = 32000 * audio.channels;  // speech
  c->time_base = AVRational{1, kOpusRate};
  c->thread_count = 1;
  if (global_header) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  av_opt_set(c->priv_data, "application", "voip", 0);
  if (int e = avcodec_open2(c, opus, nullptr); e < 0) return failed("cannot open the Opus encoder", e);

  // Sound before the face's time 0 is cut; a later start delays every packet.
  const auto channels = static_cast<std::size_t>(audio.channels);
  const std::size_t given = audio.samples.size() / channels;
  const std::size_t skip =
      audio.start < 0 ? std::min(given, static_cast<std::size_t>(std::llround(-audio.start * audio.sample_rate))) : 0;
  const std::int64_t delay = audio.start > 0 ? std::llround(audio.start * kOpusRate) : 0;
  if (skip == given) return out;  // nothing left to play

  Resampler r;
  AVChannelLayout layout;
  av_channel_layout_default(&layout, audio.channels);
  if (int e = swr_alloc_set_opts2(&r.swr, &layout, AV_SAMPLE_FMT_FLT, kOpusRate, &layout, AV_SAMPLE_FMT_FLT,
                                  audio.sample_rate, 0, nullptr);
      e < 0)
    return failed("cannot resample the audio", e);
  if (int e = swr_init(r.swr); e < 0) return failed("cannot resample the audio", e);
  const int in_count = static_cast<int>(given - skip);
  const int capacity = swr_get_out_samples(r.swr, in_count) + kOpusRate;  // room for the flush
  std::vector<float> resampled(static_cast<std::size_t>(capacity) * channels);
  std::uint8_t* dst[1] = {reinterpret_cast<std::uint8_t*>(resampled.data())};
  const std::uint8_t* src[1] = {reinterpret_cast<const std::uint8_t*>(audio.samples.data() + skip * channels)};
  int got = swr_convert(r.swr, dst, capacity, src, in_count);
  if (got < 0) return failed("cannot resample the audio", got);
  dst[0] = reinterpret_cast<std::uint8_t*>(resampled.data() + static_cast<std::size_t>(got) * channels);
  const int tail = swr_convert(r.swr, dst, capacity - got, nullptr, 0);
  if (tail < 0) return failed("cannot resample the audio", tail);
  got += tail;

  FrameOwner f;
  f.frame = av_frame_alloc();
  f.frame->format = AV_SAMPLE_FMT_FLT;
  f.frame->nb_samples = c->frame_size;
  f.frame->sample_rate = kOpusRate;
  av_channel_layout_copy(&f.frame->ch_layout, &c->ch_layout);
  if (int e = av_frame_get_buffer(f.frame, 0); e < 0) return failed("cannot allocate an audio frame", e);
  AVPacket* packet = av_packet_alloc();
  auto drain = [&]() -> int {
    for (;;) {
      const int e = avcodec_receive_packet(c, packet);
      if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return 0;
      if (e < 0) return e;
      out->packets.push_back(av_packet_clone(packet));
      av_packet_unref(packet);
    }
  };
  int status = 0;
  const auto total = static_cast<std::size_t>(got);
  for (std::size_t first = 0; first < total && status >= 0; first += static_cast<std::size_t>(c->frame_size)) {
    if ((status = av_frame_make_writable(f.frame)) < 0) break;
    auto* data = reinterpret_cast<float*>(f.frame->data[0]);
    const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(c->frame_size), total - first);
    std::fill(data, data + static_cast<std::size_t>(c->frame_size) * channels, 0.0F);  // the last frame's rest: silence
    std::copy_n(resampled.data() + first * channels, n * channels, data);
    f.frame->pts = delay + static_cast<std::int64_t>(first);
    if ((status = avcodec_send_frame(c, f.frame)) < 0) break;
    status = drain();
  }
  if (status >= 0 && (status = avcodec_send_frame(c, nullptr)) >= 0) status = drain();
  av_packet_free(&packet);
  if (status < 0) return failed("Opus encoding failed", status);
  return out;
}

}  // namespace fapc::face

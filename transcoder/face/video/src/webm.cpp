#include "fapc/face/webm.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "av_error.hpp"
#include "fapc/face/codes.hpp"
#include "fapc/face/renderer.hpp"
#include "opus_audio.hpp"

namespace fapc::face {

namespace {

// The muxer writes into memory; it seeks back to fill in sizes and cues, so the buffer is a file.
struct Memory {
  std::string bytes;
  std::int64_t at = 0;
};

// FFmpeg 5 declares the data non-const; 6 and later make it const.
int write_packet(void* opaque, std::uint8_t* data, int size) {
  auto* m = static_cast<Memory*>(opaque);
  const auto end = static_cast<std::size_t>(m->at) + static_cast<std::size_t>(size);
  if (m->bytes.size() < end) m->bytes.resize(end);
  std::memcpy(m->bytes.data() + m->at, data, static_cast<std::size_t>(size));
  m->at = static_cast<std::int64_t>(end);
  return size;
}

std::int64_t seek(void* opaque, std::int64_t offset, int whence) {
  auto* m = static_cast<Memory*>(opaque);
  whence &= ~AVSEEK_FORCE;
  if (whence == AVSEEK_SIZE) return static_cast<std::int64_t>(m->bytes.size());
  std::int64_t to = offset;
  if (whence == SEEK_CUR)
    to = m->at + offset;
  else if (whence == SEEK_END)
    to = static_cast<std::int64_t>(m->bytes.size()) + offset;
  if (to < 0) return -1;
  m->at = to;
  return to;
}

// Owners for the libav objects, so every error path frees them.
struct Output {
  AVFormatContext* format = nullptr;
  AVIOContext* io = nullptr;
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  ~Output() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (io) av_freep(&io->buffer);
    avio_context_free(&io);
    avformat_free_context(format);
  }
};

}  // namespace

std::int64_t video_frame_count(std::int64_t frames, int fps, int frame_rate) {
  const int rate = frame_rate > 0 ? frame_rate : fps;
  if (rate == fps) return std::max<std::int64_t>(1, frames);
  const double seconds = fps > 0 ? static_cast<double>(frames) / fps : 0;
  return std::max<std::int64_t>(1, std::llround(seconds * rate));
}

std::int64_t video_frame_count(const FaceTrack& track, int frame_rate) {
  return video_frame_count(track.frame_count(), track.fps(), frame_rate);
}

Status check_video(std::int64_t frames, int fps, const VideoOptions& options, const Location& at,
                   const Location& length_at) {
  if (options.width < kMinSide || options.height < kMinSide || options.width > kMaxSide || options.height > kMaxSide ||
      options.width % 2 || options.height % 2)
    return make_error(codes::video::bad_size, at,
                      "--size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                          ": a .webm needs even sides from " + std::to_string(kMinSide) + " to " +
                          std::to_string(kMaxSide) + " pixels");
  const int rate = options.frame_rate > 0 ? options.frame_rate : fps;
  if (rate > 120) return make_error(codes::video::bad_frame_rate, at, "--frame-rate must be 1 to 120");
  const double seconds = fps > 0 ? static_cast<double>(frames) / fps : 0;
  if (seconds > kMaxVideoSeconds)
    return make_error(codes::video::too_long, length_at,
                      "the animation lasts " + std::to_string(seconds) + " s; a video is limited to " +
                          std::to_string(int(kMaxVideoSeconds)) + " s");
  const std::int64_t pictures = video_frame_count(frames, fps, rate);
  // The cost, from the duration and the rate, before any picture is drawn.
  const std::int64_t picture_pixels = std::int64_t{options.width} * options.height;
  if (picture_pixels > options.limits.max_frame_pixels)
    return limit_error(at,
                       "--size " + std::to_string(options.width) + "x" + std::to_string(options.height) + " is " +
                           std::to_string(picture_pixels) + " pixels a picture",
                       Limit::frame_pixels, options.limits);
  if (pictures > options.limits.max_video_pixels / picture_pixels)
    return limit_error(length_at,
                       "the video would be " + std::to_string(pictures) + " pictures of " +
                           std::to_string(options.width) + "x" + std::to_string(options.height) + " (" +
                           std::to_string(seconds) + " s at " + std::to_string(rate) + " per second), " +
                           std::to_string(pictures * picture_pixels) + " pixels",
                       Limit::video_pixels, options.limits);
  return ok_status();
}

Result<std::string> encode_webm(const FaceTrack& track, const VideoOptions& options, const AudioInput* audio,
                                const std::string& where) {
  const Location at = Location::whole_file(where);
  if (Status checked = check_video(track.frame_count(), track.fps(), options, at, at); !checked) return checked.error();
  const int rate = options.frame_rate > 0 ? options.frame_rate : track.fps();
  const std::int64_t frames = video_frame_count(track, rate);
  auto failed = [&](const std::string& what, int code) {
    return make_error(codes::video::encoder_failed, at, what + ": " + av_message(code));
  };

  // libav logs to standard error by default; a library must not print (its errors come back as
  // return codes here). This is process-wide, like libav's logging itself.
  av_log_set_level(AV_LOG_QUIET);
  const AVCodec* vp9 = avcodec_find_encoder_by_name("libvpx-vp9");
  if (!vp9) return make_error(codes::video::no_codec, at, "this libavcodec has no libvpx-vp9 encoder");
  Output out;
  Memory memory;
  if (int e = avformat_alloc_output_context2(&out.format, nullptr, "webm", nullptr); e < 0)
    return failed("cannot start a WebM file", e);
  constexpr int kIoBuffer = 1 << 16;
  auto* buffer = static_cast<unsigned char*>(av_malloc(kIoBuffer));
  out.io = avio_alloc_context(buffer, kIoBuffer, 1, &memory, nullptr, write_packet, seek);
  out.format->pb = out.io;
  out.format->flags |= AVFMT_FLAG_CUSTOM_IO | AVFMT_FLAG_BITEXACT;

  out.codec = avcodec_alloc_context3(vp9);
  out.codec->width = options.width;
  out.codec->height = options.height;
  out.codec->time_base = AVRational{1, rate};
  out.codec->framerate = AVRational{rate, 1};
  out.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  out.codec->gop_size = rate * 2;  // a key frame every 2 s keeps scrubbing in the page quick
  out.codec->bit_rate = 0;         // constant quality (crf) instead
  out.codec->thread_count = 1;
  // swscale converts with BT.601 coefficients into limited range; say so, so players (browsers
  // assume BT.709 for untagged video) show the colours the PNG has.
  out.codec->colorspace = AVCOL_SPC_SMPTE170M;
  out.codec->color_primaries = AVCOL_PRI_SMPTE170M;
  out.codec->color_trc = AVCOL_TRC_SMPTE170M;
  out.codec->color_range = AVCOL_RANGE_MPEG;
  av_opt_set(out.codec->priv_data, "deadline", "realtime", 0);
  av_opt_set_int(out.codec->priv_data, "cpu-used", 8, 0);
  av_opt_set_int(out.codec->priv_data, "crf", 28, 0);
  if (out.format->oformat->flags & AVFMT_GLOBALHEADER) out.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if (int e = avcodec_open2(out.codec, vp9, nullptr); e < 0) return failed("cannot open the VP9 encoder", e);
  AVStream* stream = avformat_new_stream(out.format, nullptr);
  avcodec_parameters_from_context(stream->codecpar, out.codec);
  stream->time_base = out.codec->time_base;
  // The voice, coded whole before the pictures; its packets are handed to the muxer as the
  // pictures reach their times, so the file interleaves them.
  std::unique_ptr<OpusPackets> voice;
  AVStream* voice_stream = nullptr;
  if (audio) {
    auto coded = encode_opus(*audio, (out.format->oformat->flags & AVFMT_GLOBALHEADER) != 0, at);
    if (!coded) return coded.error();
    voice = std::move(*coded);
    voice_stream = avformat_new_stream(out.format, nullptr);
    avcodec_parameters_from_context(voice_stream->codecpar, voice->codec);
    voice_stream->time_base = voice->codec->time_base;
  }
  std::size_t voice_next = 0;
  // Hands over the voice's packets that start before `seconds`.
  auto write_voice = [&](double seconds) -> int {
    for (; voice && voice_next < voice->packets.size(); ++voice_next) {
      AVPacket* p = voice->packets[voice_next];
      if (static_cast<double>(p->pts) / kOpusRate >= seconds) break;
      av_packet_rescale_ts(p, voice->codec->time_base, voice_stream->time_base);
      p->stream_index = voice_stream->index;
      if (int e = av_interleaved_write_frame(out.format, p); e < 0) return e;
    }
    return 0;
  };
  if (int e = avformat_write_header(out.format, nullptr); e < 0) return failed("cannot write the WebM header", e);

  out.frame = av_frame_alloc();
  out.frame->format = AV_PIX_FMT_YUV420P;
  out.frame->width = options.width;
  out.frame->height = options.height;
  if (int e = av_frame_get_buffer(out.frame, 0); e < 0) return failed("cannot allocate a picture", e);
  out.packet = av_packet_alloc();
  // cairo's ARGB32 is one native-endian 32-bit word per pixel: libav's RGB32.
  out.scaler = sws_getContext(options.width, options.height, AV_PIX_FMT_RGB32, options.width, options.height,
                              AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr, nullptr, nullptr);

  auto drain = [&]() -> int {
    for (;;) {
      int e = avcodec_receive_packet(out.codec, out.packet);
      if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return 0;
      if (e < 0) return e;
      if (out.packet->duration == 0) out.packet->duration = 1;  // one picture: the file's duration counts the last
      av_packet_rescale_ts(out.packet, out.codec->time_base, stream->time_base);
      out.packet->stream_index = stream->index;
      if ((e = av_interleaved_write_frame(out.format, out.packet)) < 0) return e;
    }
  };

  FaceRenderer renderer(options.width, options.height);
  for (std::int64_t j = 0; j < frames; ++j) {
    const Image& picture = renderer.render(track.at_time(double(j) / rate));
    if (int e = av_frame_make_writable(out.frame); e < 0) return failed("cannot reuse a picture", e);
    const std::uint8_t* source[1] = {reinterpret_cast<const std::uint8_t*>(picture.pixels.data())};
    const int stride[1] = {picture.width * 4};
    sws_scale(out.scaler, source, stride, 0, picture.height, out.frame->data, out.frame->linesize);
    out.frame->pts = j;
    if (int e = avcodec_send_frame(out.codec, out.frame); e < 0) return failed("VP9 encoding failed", e);
    if (int e = drain(); e < 0) return failed("VP9 encoding failed", e);
    if (int e = write_voice(double(j + 1) / rate); e < 0) return failed("cannot write the Opus audio", e);
    if (options.progress) options.progress(j + 1, frames);
  }
  if (int e = avcodec_send_frame(out.codec, nullptr); e < 0) return failed("VP9 encoding failed", e);
  if (int e = drain(); e < 0) return failed("VP9 encoding failed", e);
  if (int e = write_voice(HUGE_VAL); e < 0) return failed("cannot write the Opus audio", e);
  if (int e = av_write_trailer(out.format); e < 0) return failed("cannot finish the WebM file", e);
  avio_flush(out.io);
  return std::move(memory.bytes);
}

}  // namespace fapc::face

// The voice of a .webm: mono or interleaved PCM resampled to 48 kHz (libswresample) and coded as
// Opus (libavcodec's libopus encoder), ready for the muxer.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
}

#include <memory>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/face/webm.hpp"

namespace fapc::face {

inline constexpr int kOpusRate = 48000;

struct OpusPackets {
  AVCodecContext* codec = nullptr;  // the opened encoder: the stream's parameters come from it
  std::vector<AVPacket*> packets;   // in order, times in 1/kOpusRate
  OpusPackets() = default;
  OpusPackets(const OpusPackets&) = delete;
  OpusPackets& operator=(const OpusPackets&) = delete;
  ~OpusPackets();
};

// `global_header`: the container wants the configuration (OpusHead) out of band, as WebM does.
// Packets start at audio.start seconds; sound before 0 is cut. Unsupported when libav has no
// libopus encoder.
Result<std::unique_ptr<OpusPackets>> encode_opus(const AudioInput& audio, bool global_header, const Location& at);

}  // namespace fapc::face

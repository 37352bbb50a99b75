// libFuzzer target: the WAV reader and the mix. Declared chunk sizes, rates and channel counts
// are the input's: the reader must never read past the bytes, allocate more samples than they
// hold, or accept a rate outside 1 to 384000 Hz; every error carries a byte offset. An accepted
// clip is mixed with itself placed far away and at another rate, under a small sample limit:
// the mix either fits the limit or is refused by it (issue 32: 1 Hz with 384 kHz, clips hours
// apart), never allocates past it.
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "fapc/transcoder/audio_mix.hpp"
#include "fapc/transcoder/wav.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  auto clip = fapc::read_wav(bytes, "fuzz.wav");
  if (!clip.ok()) {
    if (clip.error().where.byte_offset < 0 || clip.error().where.byte_offset > static_cast<std::int64_t>(size))
      std::abort();
    return 0;
  }
  if (clip->sample_rate < 1 || clip->sample_rate > 384000 || clip->samples.size() > size / 2) std::abort();
  fapc::Limits limits;
  limits.max_audio_samples = std::int64_t{1} << 20;
  std::vector<fapc::AudioClip> clips = {*clip, *clip};
  // The second copy: later by as many seconds as the first byte says (up to 255 hours), at 8 kHz.
  clips[1].begin = size > 0 ? 3600.0 * data[0] : 0;
  clips[1].sample_rate = 8000;
  auto mixed = fapc::mix_audio(clips, 1e9, limits);
  if (mixed.ok()) {
    if (*mixed && static_cast<std::int64_t>((*mixed)->samples.size()) > limits.max_audio_samples) std::abort();
  } else if (mixed.error().kind != fapc::ErrorKind::limit_exceeded) {
    std::abort();
  }
  return 0;
}

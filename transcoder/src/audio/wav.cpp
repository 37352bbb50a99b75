// RIFF WAVE: "RIFF" size "WAVE", then chunks (4-byte id, 32-bit little-endian size, data padded to
// an even length). PCM is format tag 1 (or WAVE_FORMAT_EXTENSIBLE 0xFFFE with the PCM subformat).
#include <cstring>

#include "fapc/transcoder/codes.hpp"
#include "fapc/transcoder/wav.hpp"

namespace fapc {
namespace {

std::uint32_t u32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}
std::uint16_t u16(std::string_view b, std::size_t at) {
  return static_cast<std::uint16_t>(static_cast<unsigned char>(b[at]) | static_cast<unsigned char>(b[at + 1]) << 8);
}
void put32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
void put16(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xFF));
  out.push_back(static_cast<char>(v >> 8));
}

Diagnostic at(ErrorCode code, const std::string& file, std::size_t byte, std::string message) {
  return make_error(code, Location{file, 0, 0, static_cast<std::int64_t>(byte)}, std::move(message));
}

}  // namespace

Result<AudioClip> read_wav(std::string_view b, const std::string& file) {
  if (b.size() < 12 || b.substr(0, 4) != "RIFF" || b.substr(8, 4) != "WAVE")
    return at(codes::wav::not_wav, file, 0, "not a WAV file (no RIFF WAVE header)");
  std::size_t pos = 12;
  bool have_format = false;
  int channels = 0;
  int rate = 0;
  std::size_t format_at = 0;
  while (pos + 8 <= b.size()) {
    const std::string_view id = b.substr(pos, 4);
    const std::uint64_t size = u32(b, pos + 4);
    const std::size_t body = pos + 8;
    if (body + size > b.size())
      return at(codes::wav::truncated_chunk, file, pos,
                "the WAV chunk '" + std::string(id) + "' runs past the end of the file");
    if (id == "fmt ") {
      if (size < 16) return at(codes::wav::bad_format_chunk, file, pos, "the WAV fmt chunk is too short");
      format_at = pos;
      int tag = u16(b, body);
      channels = u16(b, body + 2);
      rate = static_cast<int>(std::min<std::uint32_t>(u32(b, body + 4), 1u << 30));
      const int bits = u16(b, body + 14);
      if (tag == 0xFFFE && size >= 40) tag = u16(b, body + 24);  // WAVE_FORMAT_EXTENSIBLE: the subformat's tag
      if (tag != 1) {
        const char* name = tag == 3   ? "32-bit float"
                           : tag == 6 ? "A-law"
                           : tag == 7 ? "mu-law"
                           : tag == 2 ? "ADPCM"
                                      : "non-PCM";
        return at(codes::wav::unsupported_format, file, body,
                  std::string("the WAV file is ") + name + " (format " + std::to_string(tag) +
                      "); fapc reads 16-bit PCM WAV only: convert it, e.g. ffmpeg -i IN -c:a pcm_s16le OUT.wav");
      }
      if (bits != 16)
        return at(codes::wav::unsupported_format, file, body + 14,
                  "the WAV file is " + std::to_string(bits) +
                      "-bit PCM; fapc reads 16-bit PCM WAV only: convert it, e.g. ffmpeg -i IN -c:a pcm_s16le OUT.wav");
      if (channels < 1 || channels > 64)
        return at(codes::wav::bad_format_chunk, file, body + 2,
                  "the WAV file has " + std::to_string(channels) + " channels (1 to 64)");
      if (rate < 1 || rate > 384000)
        return at(codes::wav::bad_format_chunk, file, body + 4,
                  "the WAV sample rate " + std::to_string(rate) + " Hz is outside 1 to 384000");
      have_format = true;
    } else if (id == "data") {
      if (!have_format)
        return at(codes::wav::data_before_format, file, pos, "the WAV data chunk comes before any fmt chunk");
      AudioClip clip;
      clip.sample_rate = rate;
      clip.source = Location{file, 0, 0, static_cast<std::int64_t>(format_at)};
      const std::size_t frames = size / (2 * static_cast<std::size_t>(channels));
      clip.samples.resize(frames);
      for (std::size_t f = 0; f < frames; ++f) {
        long sum = 0;  // several channels: their mean
        for (int c = 0; c < channels; ++c)
          sum += static_cast<std::int16_t>(
              u16(b, body + 2 * (f * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c))));
        clip.samples[f] = static_cast<std::int16_t>(sum / channels);
      }
      return clip;
    }
    pos = body + size + (size & 1);
  }
  return at(codes::wav::missing_chunk, file, b.size(),
            have_format ? "the WAV file has no data chunk" : "the WAV file has no fmt chunk");
}

std::string wav_bytes(const AudioTrack& track) {
  const auto lead = static_cast<std::size_t>(track.start > 0 ? track.start * track.sample_rate + 0.5 : 0);
  const std::size_t count = lead + track.samples.size();
  const auto data_size = static_cast<std::uint32_t>(count * 2);
  std::string out;
  out.reserve(44 + count * 2);
  out += "RIFF";
  put32(out, 36 + data_size);
  out += "WAVEfmt ";
  put32(out, 16);
  put16(out, 1);  // PCM
  put16(out, 1);  // mono
  put32(out, static_cast<std::uint32_t>(track.sample_rate));
  put32(out, static_cast<std::uint32_t>(track.sample_rate) * 2);  // bytes per second
  put16(out, 2);                                                  // bytes per frame
  put16(out, 16);
  out += "data";
  put32(out, data_size);
  out.append(lead * 2, '\0');
  for (const std::int16_t s : track.samples) put16(out, static_cast<std::uint16_t>(s));
  return out;
}

}  // namespace fapc

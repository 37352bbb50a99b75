#include "engine_output.hpp"

#include <algorithm>
#include <cstring>

namespace fapc::speech {
namespace {

// Same machine, same build at both ends: numbers travel in the host's own byte order.
template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

struct Reader {
  std::string_view bytes;
  bool ok = true;
  template <class T>
  T take() {
    T value{};
    if (bytes.size() < sizeof value) {
      ok = false;
      return value;
    }
    std::memcpy(&value, bytes.data(), sizeof value);
    bytes.remove_prefix(sizeof value);
    return value;
  }
  std::string text() {
    const std::uint64_t n = count(1);
    std::string out(bytes.substr(0, n));
    bytes.remove_prefix(n);
    return out;
  }
  // A count of items of `item_size` bytes each, refused when the rest cannot hold them.
  std::uint64_t count(std::size_t item_size) {
    const auto n = take<std::uint64_t>();
    if (n > bytes.size() / item_size) ok = false;
    return ok ? n : 0;
  }
};

void put_text(std::string& out, std::string_view text) {
  put(out, static_cast<std::uint64_t>(text.size()));
  out.append(text);
}

constexpr std::size_t kNameBytes = 8;  // eSpeak NG's phoneme mnemonics are at most 8 bytes

}  // namespace

std::string encode(const EngineOutput& output) {
  std::string out;
  out.reserve(32 + output.samples.size() * 2 + output.phonemes.size() * 12 + output.words.size() * 8);
  put(out, static_cast<std::uint8_t>(output.stop));
  put(out, output.synth_status);
  put(out, static_cast<std::uint64_t>(output.samples.size()));
  out.append(reinterpret_cast<const char*>(output.samples.data()), output.samples.size() * sizeof(std::int16_t));
  put(out, static_cast<std::uint64_t>(output.phonemes.size()));
  for (const auto& [name, ms] : output.phonemes) {
    char fixed[kNameBytes] = {};
    std::memcpy(fixed, name.data(), std::min(name.size(), kNameBytes));
    out.append(fixed, kNameBytes);
    put(out, ms);
  }
  put(out, static_cast<std::uint64_t>(output.words.size()));
  for (const auto& [position, ms] : output.words) {
    put(out, position);
    put(out, ms);
  }
  return out;
}

std::optional<EngineOutput> decode_engine_output(std::string_view bytes) {
  Reader in{bytes};
  EngineOutput out;
  const auto stop = in.take<std::uint8_t>();
  if (stop > static_cast<std::uint8_t>(EngineOutput::Stop::synth_failed)) return std::nullopt;
  out.stop = static_cast<EngineOutput::Stop>(stop);
  out.synth_status = in.take<std::int32_t>();
  out.samples.resize(in.count(sizeof(std::int16_t)));
  if (!out.samples.empty()) std::memcpy(out.samples.data(), in.bytes.data(), out.samples.size() * sizeof(std::int16_t));
  in.bytes.remove_prefix(out.samples.size() * sizeof(std::int16_t));
  out.phonemes.resize(in.count(kNameBytes + sizeof(std::int32_t)));
  for (auto& [name, ms] : out.phonemes) {
    const std::string_view fixed = in.bytes.substr(0, kNameBytes);
    name.assign(fixed.data(), std::min(fixed.size(), fixed.find('\0')));
    in.bytes.remove_prefix(kNameBytes);
    ms = in.take<std::int32_t>();
  }
  out.words.resize(in.count(2 * sizeof(std::int32_t)));
  for (auto& [position, ms] : out.words) {
    position = in.take<std::int32_t>();
    ms = in.take<std::int32_t>();
  }
  if (!in.ok || !in.bytes.empty()) return std::nullopt;
  return out;
}

std::string encode(const EngineRequest& request) {
  std::string out;
  put_text(out, request.language);
  put_text(out, request.voice);
  put(out, request.words_per_minute);
  put(out, request.max_samples);
  put_text(out, request.text);
  return out;
}

std::optional<EngineRequest> decode_engine_request(std::string_view bytes) {
  Reader in{bytes};
  EngineRequest out;
  out.language = in.text();
  out.voice = in.text();
  out.words_per_minute = in.take<std::int32_t>();
  out.max_samples = in.take<std::uint64_t>();
  out.text = in.text();
  if (!in.ok || !in.bytes.empty()) return std::nullopt;
  return out;
}

}  // namespace fapc::speech

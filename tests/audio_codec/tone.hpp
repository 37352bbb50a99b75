// A test voice that is easy to check: 440 Hz tone and silence in known stretches.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <tuple>
#include <vector>

#include "fapc/timeline/audio.hpp"

namespace fapc::test {

// [from, to) sample ranges and whether the tone sounds there: 0.2 s silence, 0.5 s tone, 0.3 s
// silence, 0.4 s tone, 0.2 s silence (1.6 s).
inline std::vector<std::tuple<std::size_t, std::size_t, bool>> tone_segments(int rate) {
  const double stretches[] = {0.2, 0.5, 0.3, 0.4, 0.2};
  std::vector<std::tuple<std::size_t, std::size_t, bool>> out;
  double t = 0;
  for (int i = 0; i < 5; ++i) {
    const auto from = static_cast<std::size_t>(std::lround(t * rate));
    t += stretches[i];
    out.emplace_back(from, static_cast<std::size_t>(std::lround(t * rate)), i % 2 == 1);
  }
  return out;
}

inline AudioTrack tone_with_silences(int rate, double start = 0) {
  AudioTrack a;
  a.sample_rate = rate;
  a.start = start;
  for (const auto& [from, to, loud] : tone_segments(rate))
    for (std::size_t k = from; k < to; ++k)
      a.samples.push_back(loud ? static_cast<std::int16_t>(
                                     std::lround(16000 * std::sin(2 * std::numbers::pi * 440.0 * double(k) / rate)))
                               : std::int16_t{0});
  return a;
}

inline double rms(const std::vector<std::int16_t>& s, std::size_t from, std::size_t to) {
  double sum = 0;
  for (std::size_t k = from; k < to; ++k) sum += double(s[k]) * s[k];
  return to > from ? std::sqrt(sum / double(to - from)) : 0;
}

}  // namespace fapc::test

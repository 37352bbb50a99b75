#include <algorithm>
#include <cmath>

#include "fapc/transcoder/audio_mix.hpp"

namespace fapc {
namespace {

// The clip's sample at fractional index x (linear between neighbours, 0 outside).
double sample_at(const AudioClip& clip, double x) {
  if (x < 0) return 0;
  const auto i = static_cast<std::size_t>(x);
  if (i >= clip.samples.size()) return 0;
  const double a = clip.samples[i];
  const double b = i + 1 < clip.samples.size() ? clip.samples[i + 1] : 0.0;
  return a + (b - a) * (x - static_cast<double>(i));
}

}  // namespace

std::optional<AudioClip> placed_audio(const AudioClip& clip, double shift, double from, double to) {
  if (clip.sample_rate <= 0 || clip.samples.empty()) return std::nullopt;
  const double begin = clip.begin + shift;
  const double rate = clip.sample_rate;
  const auto count = static_cast<double>(clip.samples.size());
  const double first = std::clamp(std::ceil((from - begin) * rate - 1e-6), 0.0, count);
  const double last = std::clamp(std::ceil((to - begin) * rate - 1e-6), 0.0, count);
  if (last <= first) return std::nullopt;
  AudioClip out;
  out.sample_rate = clip.sample_rate;
  out.source = clip.source;
  out.begin = begin + first / rate;
  out.samples.assign(clip.samples.begin() + static_cast<std::ptrdiff_t>(first),
                     clip.samples.begin() + static_cast<std::ptrdiff_t>(last));
  return out;
}

Result<std::optional<AudioTrack>> mix_audio(const std::vector<AudioClip>& clips, double max_seconds) {
  std::optional<AudioTrack> none;
  int rate = 0;
  double start = 0;
  double end = 0;
  const AudioClip* furthest = nullptr;
  bool first = true;
  for (const AudioClip& clip : clips) {
    if (clip.sample_rate <= 0 || clip.samples.empty()) continue;
    const double clip_end = clip.begin + static_cast<double>(clip.samples.size()) / clip.sample_rate;
    if (clip_end <= 0) continue;
    rate = std::max(rate, clip.sample_rate);
    start = first ? std::max(0.0, clip.begin) : std::min(start, std::max(0.0, clip.begin));
    if (first || clip_end > end) {
      end = clip_end;
      furthest = &clip;
    }
    first = false;
  }
  if (first) return none;
  if (end - start > max_seconds) {
    return make_error(ErrorKind::limit_exceeded, furthest->source,
                      "the audio would last " + std::to_string(end - start) + " s, more than the limit of " +
                          std::to_string(max_seconds) + " s (the frame limit, --max-frames, at the frame rate)");
  }
  AudioTrack track;
  track.sample_rate = rate;
  track.start = start;
  // Less 1e-6 like the cuts above: a clip of n samples moved to 1 s ends at 1 + n/rate, which
  // times the rate can round to just over n and would add a silent sample.
  const auto length = static_cast<std::size_t>(std::max(0.0, std::ceil((end - start) * rate - 1e-6)));
  std::vector<double> sum(length, 0.0);
  for (const AudioClip& clip : clips) {
    if (clip.sample_rate <= 0 || clip.samples.empty()) continue;
    const double step = static_cast<double>(clip.sample_rate) / rate;  // clip samples per track sample
    const double offset = (clip.begin - start) * rate;                  // track index of clip sample 0
    const auto from = static_cast<std::size_t>(std::max(0.0, std::ceil(offset)));
    const double clip_length = static_cast<double>(clip.samples.size()) / step;
    const auto to = std::min(length, static_cast<std::size_t>(std::max(0.0, std::ceil(offset + clip_length))));
    for (std::size_t n = from; n < to; ++n) sum[n] += sample_at(clip, (static_cast<double>(n) - offset) * step);
  }
  track.samples.resize(length);
  for (std::size_t n = 0; n < length; ++n)
    track.samples[n] = static_cast<std::int16_t>(std::clamp(std::lround(sum[n]), -32768L, 32767L));
  return std::optional<AudioTrack>(std::move(track));
}

}  // namespace fapc

#include <algorithm>
#include <cmath>

#include "fapc/transcoder/audio_mix.hpp"
#include "fapc/transcoder/codes.hpp"

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

double placed_samples(const AudioClip& clip, double shift, double from, double to) {
  if (clip.sample_rate <= 0 || clip.samples.empty()) return 0;
  const double begin = clip.begin + shift;
  const double rate = clip.sample_rate;
  const auto count = static_cast<double>(clip.samples.size());
  const double first = std::clamp(std::ceil((from - begin) * rate - 1e-6), 0.0, count);
  const double last = std::clamp(std::ceil((to - begin) * rate - 1e-6), 0.0, count);
  return std::max(0.0, last - first);
}

Result<std::optional<AudioTrack>> mix_audio(const std::vector<AudioClip>& clips, double max_seconds,
                                            const Limits& limits) {
  std::optional<AudioTrack> none;
  int rate = 0;
  double start = 0;
  double end = 0;
  const AudioClip* furthest = nullptr;
  const AudioClip* fastest = nullptr;
  bool first = true;
  for (const AudioClip& clip : clips) {
    if (clip.sample_rate <= 0 || clip.samples.empty()) continue;
    const double clip_end = clip.begin + static_cast<double>(clip.samples.size()) / clip.sample_rate;
    if (clip_end <= 0) continue;
    if (clip.sample_rate > rate) {
      rate = clip.sample_rate;
      fastest = &clip;
    }
    start = first ? std::max(0.0, clip.begin) : std::min(start, std::max(0.0, clip.begin));
    if (first || clip_end > end) {
      end = clip_end;
      furthest = &clip;
    }
    first = false;
  }
  if (first) return none;
  if (end - start > max_seconds) {
    return make_error(codes::limit::frames, furthest->source,
                      "the audio would last " + std::to_string(end - start) + " s, more than the limit of " +
                          std::to_string(max_seconds) + " s (the frame limit, --max-frames, at the frame rate)");
  }
  // Less 1e-6 like the cuts above: a clip of n samples moved to 1 s ends at 1 + n/rate, which
  // times the rate can round to just over n and would add a silent sample.
  const double samples = std::max(0.0, std::ceil((end - start) * rate - 1e-6));
  if (samples > static_cast<double>(limits.max_audio_samples)) {
    return limit_error(furthest->source,
                       "the audio from " + std::to_string(start) + " s to " + std::to_string(end) + " s at " +
                           std::to_string(rate) + " Hz spans " + std::to_string(static_cast<std::int64_t>(samples)) +
                           " samples",
                       Limit::audio_samples, limits);
  }
  AudioTrack track;
  track.sample_rate = rate;
  track.start = start;
  track.source = fastest->source;
  const auto length = static_cast<std::size_t>(samples);
  track.samples.resize(length);
  // Each clip's span of track samples; the clips are then summed one block at a time, those
  // that overlap the block only, so the sum never takes more than a block.
  struct Span {
    const AudioClip* clip;
    double step, offset;
    std::size_t from, to;
  };
  std::vector<Span> spans;
  for (const AudioClip& clip : clips) {
    if (clip.sample_rate <= 0 || clip.samples.empty()) continue;
    const double step = static_cast<double>(clip.sample_rate) / rate;  // clip samples per track sample
    const double offset = (clip.begin - start) * rate;                 // track index of clip sample 0
    const auto from = static_cast<std::size_t>(std::max(0.0, std::ceil(offset)));
    const double clip_length = static_cast<double>(clip.samples.size()) / step;
    const auto to = std::min(length, static_cast<std::size_t>(std::max(0.0, std::ceil(offset + clip_length))));
    if (from < to) spans.push_back({&clip, step, offset, from, to});
  }
  std::stable_sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.from < b.from; });
  constexpr std::size_t kBlock = 1 << 16;
  std::vector<double> sum;
  std::vector<const Span*> active;
  std::size_t next = 0;
  for (std::size_t block = 0; block < length; block += kBlock) {
    const std::size_t block_end = std::min(length, block + kBlock);
    std::erase_if(active, [block](const Span* s) { return s->to <= block; });
    for (; next < spans.size() && spans[next].from < block_end; ++next) active.push_back(&spans[next]);
    if (active.empty()) continue;  // silence: the track is already zero
    sum.assign(block_end - block, 0.0);
    for (const Span* s : active) {
      const std::size_t to = std::min(s->to, block_end);
      for (std::size_t n = std::max(s->from, block); n < to; ++n)
        sum[n - block] += sample_at(*s->clip, (static_cast<double>(n) - s->offset) * s->step);
    }
    for (std::size_t n = block; n < block_end; ++n)
      track.samples[n] = static_cast<std::int16_t>(std::clamp(std::lround(sum[n - block]), -32768L, 32767L));
  }
  return std::optional<AudioTrack>(std::move(track));
}

}  // namespace fapc

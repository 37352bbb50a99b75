// The coarticulation rule of docs/speech.md: viseme spans to cross-fading viseme.* clips.
#include <algorithm>
#include <cmath>

#include "fapc/codec/fap_table.hpp"
#include "fapc/transcoder/speech.hpp"

namespace fapc {
namespace {

constexpr double kWeight = 63;   // a viseme at full strength (FAP 1's blend range)
constexpr double kTouch = 1e-9;  // spans closer than this are neighbours, not separated by silence

bool is_pause(const std::string& name) { return !name.empty() && name[0] == '_'; }

// Short spans first widened around their centre; where that makes neighbours overlap, the
// widened one keeps its time (both widened: they split the overlap).
void widen_short_spans(std::vector<VisemeSpan>& spans, double min_hold) {
  std::vector<bool> widened(spans.size(), false);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    VisemeSpan& s = spans[i];
    if (s.end - s.begin >= min_hold) continue;
    const double centre = (s.begin + s.end) / 2;
    s.begin = std::max(0.0, centre - min_hold / 2);
    s.end = s.begin + min_hold;
    widened[i] = true;
  }
  for (std::size_t i = 0; i + 1 < spans.size(); ++i) {
    VisemeSpan& a = spans[i];
    VisemeSpan& b = spans[i + 1];
    if (a.end <= b.begin) continue;
    if (widened[i] && !widened[i + 1]) {
      b.begin = a.end;
    } else if (widened[i + 1] && !widened[i]) {
      a.end = b.begin;
    } else {
      const double middle = (a.end + b.begin) / 2;
      a.end = middle;
      b.begin = middle;
    }
  }
  std::erase_if(spans, [](const VisemeSpan& s) { return s.end <= s.begin; });
}

}  // namespace

std::vector<VisemeSpan> viseme_spans(const std::vector<SpokenPhoneme>& phonemes) {
  std::vector<VisemeSpan> spans;
  for (std::size_t i = 0; i < phonemes.size(); ++i) {
    const SpokenPhoneme& p = phonemes[i];
    if (is_pause(p.name) || p.end <= p.begin) continue;
    int viseme = p.viseme;
    // No mouth shape of its own (h, a glottal stop): the mouth is already on its way to the next
    // sound of the word, else it stays where the previous one left it.
    for (std::size_t k = i + 1; viseme == 0 && k < phonemes.size() && !is_pause(phonemes[k].name); ++k)
      viseme = phonemes[k].viseme;
    for (std::size_t k = i; viseme == 0 && k-- > 0 && !is_pause(phonemes[k].name);) viseme = phonemes[k].viseme;
    if (viseme <= 0) continue;
    if (!spans.empty() && spans.back().viseme == viseme && std::abs(spans.back().end - p.begin) < kTouch) {
      spans.back().end = p.end;
    } else {
      spans.push_back(VisemeSpan{viseme, p.begin, p.end});
    }
  }
  return spans;
}

std::vector<Clip> coarticulated_viseme_clips(std::vector<VisemeSpan> spans, double stretch, const Coarticulation& rule,
                                             const Location& where) {
  for (VisemeSpan& s : spans) {
    s.begin *= stretch;
    s.end *= stretch;
  }
  widen_short_spans(spans, rule.min_hold);
  std::vector<Clip> clips;
  clips.reserve(spans.size());
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const VisemeSpan& s = spans[i];
    const double length = s.end - s.begin;
    // Half of each edge's fade: at most half of this span and half of what lies on the other
    // side (the neighbour, or the silence), so the two fades of one span never meet.
    const auto half_fade = [&](double other) { return std::min({rule.fade / 2, length / 2, other / 2}); };
    // Before the first sound the fade fits between the utterance's start and the sound (the face
    // is neutral when the talk begins); after the last one it runs its full length.
    const double before = i == 0
                              ? 2 * s.begin
                              : (std::abs(spans[i - 1].end - s.begin) < kTouch ? spans[i - 1].end - spans[i - 1].begin
                                                                               : s.begin - spans[i - 1].end);
    const double after = i + 1 == spans.size()
                             ? rule.fade
                             : (std::abs(spans[i + 1].begin - s.end) < kTouch ? spans[i + 1].end - spans[i + 1].begin
                                                                              : spans[i + 1].begin - s.end);
    const double in = half_fade(before);
    const double out = half_fade(after);
    Clip clip;
    clip.target = "viseme." + std::string(viseme_name(s.viseme));
    clip.begin = s.begin - in;
    clip.end = s.end + out;
    const double span = clip.end - clip.begin;
    const double weight = kWeight * s.weight;
    clip.curve.keys = {KeyPoint{0, 0}, KeyPoint{2 * in, weight}, KeyPoint{span - 2 * out, weight}, KeyPoint{span, 0}};
    clip.source = where;
    clips.push_back(std::move(clip));
  }
  return clips;
}

}  // namespace fapc

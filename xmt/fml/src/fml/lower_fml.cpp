#include <algorithm>
#include <map>

#include "fapc/codec/fap_table.hpp"
#include "fapc/transcoder/audio_mix.hpp"
#include "fapc/transcoder/profile.hpp"
#include "fml/embedded_fml.hpp"
#include "fml/fml_tree.hpp"

namespace fapc::xmt {
namespace {

// The clip of one move run: a linear ramp over the run's simple duration, held afterwards.
Clip ramp_clip(const std::string& target, double from, double to, const Occurrence& run, const Location& where) {
  Clip clip;
  clip.target = target;
  clip.begin = run.begin;
  clip.end = run.end;
  clip.curve_offset = run.curve_offset;
  clip.curve = Curve::ramp(from, to, run.simple_duration, Interpolation::linear);
  clip.blend = BlendMode::overwrite;
  clip.fill = Fill::freeze;
  clip.source = where;
  return clip;
}

// The value a target has at t, given the clips placed before (all overwrite and frozen, so the
// one that began last decides, held at its end).
double current_value(const std::map<std::string, Clip>& latest, const std::string& target, double t) {
  const auto found = latest.find(target);
  if (found == latest.end()) return 0;
  const Clip& clip = found->second;
  return clip.curve.value_at(clip.local_time(std::min(t, clip.end)));
}

// One run of a talk: its visemes and audio from the run's (possibly cut) start, cut at its end.
void place_talk(const FmlLeaf& leaf, const Occurrence& run, const Coarticulation& rule, Timeline& out) {
  const double shift = run.begin - run.curve_offset;
  const Timeline talk = talk_timeline(*leaf.talk, leaf.where, run.simple_duration, rule);
  for (const Clip& inner : talk.clips) {
    Clip clip = inner;
    clip.begin = std::max(inner.begin + shift, run.begin);
    clip.end = std::min(inner.end + shift, run.end);
    if (clip.end <= clip.begin) continue;
    clip.curve_offset = inner.curve_offset + (clip.begin - (inner.begin + shift));
    out.clips.push_back(std::move(clip));
  }
  for (const AudioClip& voice : talk.audio)
    if (auto placed = placed_audio(voice, shift, run.begin, run.end)) out.audio.push_back(std::move(*placed));
}

}  // namespace

Timeline talk_timeline(const FmlTalk& talk, const Location& where, double duration, const Coarticulation& rule) {
  Timeline out;
  const Speech& speech = talk.speech;
  const double natural = std::max(talk.natural, speech.duration);
  if (natural <= 0) return out;
  const bool spoken = !talk.audio.samples.empty();
  const double stretch = spoken ? 1.0 : duration / natural;
  out.clips = coarticulated_viseme_clips(speech.visemes, stretch, rule, where);
  if (spoken) out.audio.push_back(talk.audio);
  out.explicit_end = duration;
  out.end_source = where;
  return out;
}

Timeline lower_fml(const FmlTree& tree, const Schedule& schedule) {
  std::vector<const Occurrence*> runs;
  for (const Occurrence& run : schedule.occurrences)
    if (run.end > run.begin) runs.push_back(&run);  // cut to nothing by an ancestor
  std::stable_sort(runs.begin(), runs.end(),
                   [](const Occurrence* a, const Occurrence* b) { return a->begin < b->begin; });
  Timeline timeline;
  // A clip per run, but for talks (a clip per viseme) and normal moves (one per expression).
  timeline.clips.reserve(runs.size());
  std::map<std::string, Clip> latest;
  const auto place_move = [&](const std::string& target, double to, const Occurrence& run, const Location& where) {
    Clip clip = ramp_clip(target, current_value(latest, target, run.begin), to, run, where);
    latest[target] = clip;
    timeline.clips.push_back(std::move(clip));
  };
  for (const Occurrence* run : runs) {
    const FmlLeaf& leaf = tree.leaves[run->leaf_id];
    switch (leaf.kind) {
      case FmlLeaf::Kind::move:
        place_move(tree.targets[leaf.target], leaf.value, *run, leaf.where);
        break;
      case FmlLeaf::Kind::normal: {
        std::vector<std::string> expressions;
        for (const auto& [target, clip] : latest)
          if (weight_target(target) && weight_target(target)->fap == 2) expressions.push_back(target);
        for (const std::string& target : expressions) place_move(target, 0, *run, leaf.where);
        break;
      }
      case FmlLeaf::Kind::talk:
        place_talk(leaf, *run, tree.coarticulation, timeline);
        break;
      case FmlLeaf::Kind::wait:
        break;
    }
  }
  timeline.explicit_end = schedule.end;
  timeline.end_source = story_end_source(tree, schedule);
  return timeline;
}

Location story_end_source(const FmlTree& tree, const Schedule& schedule) {
  return end_source(schedule, tree.root.source, [&](std::size_t leaf) { return tree.leaves[leaf].where; });
}

}  // namespace fapc::xmt

#include <algorithm>
#include <map>

#include "fapc/codec/fap_table.hpp"
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

// One run of a talk: its visemes from the run's (possibly cut) start, cut at the run's end.
void place_talk(const FmlLeaf& leaf, const Occurrence& run, std::vector<Clip>& out) {
  const double shift = run.begin - run.curve_offset;
  for (Clip clip : viseme_clips(leaf.speech, run.simple_duration, leaf.where)) {
    clip.begin = std::max(clip.begin + shift, run.begin);
    clip.end = std::min(clip.end + shift, run.end);
    if (clip.end > clip.begin) out.push_back(std::move(clip));
  }
}

}  // namespace

std::vector<Clip> viseme_clips(const Speech& speech, double duration, const Location& where) {
  std::vector<Clip> clips;
  if (speech.duration <= 0) return clips;
  const double stretch = duration / speech.duration;
  for (const VisemeSpan& span : speech.visemes) {
    Clip clip;
    clip.target = "viseme." + std::string(viseme_name(span.viseme));
    clip.begin = span.begin * stretch;
    clip.end = span.end * stretch;
    clip.curve = Curve::constant(63);
    clip.source = where;
    clips.push_back(std::move(clip));
  }
  return clips;
}

Timeline lower_fml(const FmlTree& tree, const Schedule& schedule) {
  std::vector<const Occurrence*> runs;
  for (const Occurrence& run : schedule.occurrences)
    if (run.end > run.begin) runs.push_back(&run);  // cut to nothing by an ancestor
  std::stable_sort(runs.begin(), runs.end(), [](const Occurrence* a, const Occurrence* b) { return a->begin < b->begin; });
  Timeline timeline;
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
        place_move(leaf.target, leaf.value, *run, leaf.where);
        break;
      case FmlLeaf::Kind::normal: {
        std::vector<std::string> expressions;
        for (const auto& [target, clip] : latest)
          if (weight_target(target) && weight_target(target)->fap == 2) expressions.push_back(target);
        for (const std::string& target : expressions) place_move(target, 0, *run, leaf.where);
        break;
      }
      case FmlLeaf::Kind::talk:
        place_talk(leaf, *run, timeline.clips);
        break;
      case FmlLeaf::Kind::wait:
        break;
    }
  }
  timeline.explicit_end = schedule.end;
  return timeline;
}

}  // namespace fapc::xmt

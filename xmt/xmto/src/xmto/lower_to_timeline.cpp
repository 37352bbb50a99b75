#include <algorithm>
#include <map>
#include <set>
#include <string_view>

#include "fapc/transcoder/audio_mix.hpp"
#include "fapc/transcoder/growing_timeline.hpp"
#include "fapc/transcoder/render.hpp"
#include "xmto/xmto_tree.hpp"

namespace fapc::xmt {
namespace {

struct TaggedClip {
  std::size_t leaf;
  Clip clip;
};

// The included animation's clips and audio for one run: shifted to the run's begin, cut at its end.
void place_included(const Leaf& leaf, std::size_t id, const Occurrence& run,
                    std::vector<TaggedClip>& out, std::vector<AudioClip>& audio) {
  const double shift = run.begin - run.curve_offset;
  for (const AudioClip& sound : leaf.included->audio)
    if (auto placed = placed_audio(sound, shift, run.begin, run.end)) audio.push_back(std::move(*placed));
  for (const Clip& inner : leaf.included->clips) {
    Clip clip = inner;
    clip.begin = std::max(inner.begin + shift, run.begin);
    clip.end = std::min(inner.end + shift, run.end);
    if (clip.end <= clip.begin) continue;
    clip.curve_offset = inner.curve_offset + (clip.begin - (inner.begin + shift));
    if (leaf.fill == Fill::freeze) clip.fill = Fill::freeze;
    out.push_back(TaggedClip{id, std::move(clip)});
  }
}

Clip animate_clip(const Leaf& leaf, const Occurrence& run, double underlying) {
  Clip clip;
  clip.target = leaf.target;
  clip.begin = run.begin;
  clip.end = run.end;
  clip.curve_offset = run.curve_offset;
  clip.curve = leaf.function.curve(underlying, run.iteration);
  clip.blend = leaf.function.blend;
  clip.fill = leaf.fill;
  clip.source = leaf.where;
  return clip;
}

// To-animations start from the value their target has without them when each run begins, so
// they are placed after everything else, element by element in order of their first begin; each
// element sees the clips placed before it (to-animations of earlier elements included), not its
// own runs. One GrowingTimeline over the targets that have to-animations answers every run in
// O(log n) instead of an evaluator built per element over all its target's clips.
void place_to_animations(const XmtoTree& tree, const std::map<std::size_t, std::vector<Occurrence>>& runs,
                         std::vector<TaggedClip>& clips) {
  if (runs.empty()) return;
  std::vector<std::size_t> order;
  for (const auto& [id, list] : runs) order.push_back(id);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return runs.at(a).front().begin < runs.at(b).front().begin;
  });
  std::set<std::string_view> targets;
  for (const std::size_t id : order) targets.insert(tree.leaves[id].target);
  // Every clip the growing timeline will hold: those placed so far, then the runs in order.
  std::vector<Clip> planned;
  std::vector<std::size_t> placed;  // indices into `clips` of the planned clips placed so far
  for (std::size_t i = 0; i < clips.size(); ++i) {
    if (!targets.contains(clips[i].clip.target)) continue;
    placed.push_back(i);
    Clip shape = clips[i].clip;
    shape.curve = Curve{};
    planned.push_back(std::move(shape));
  }
  for (const std::size_t id : order) {
    for (const Occurrence& run : runs.at(id)) {
      Clip shape = animate_clip(tree.leaves[id], run, 0);
      shape.curve = Curve{};
      planned.push_back(std::move(shape));
    }
  }
  GrowingTimeline underneath(planned);
  std::size_t next = 0;
  for (const std::size_t i : placed) underneath.add(next++, clips[i].clip);
  for (const std::size_t id : order) {
    const Leaf& leaf = tree.leaves[id];
    const std::size_t first = clips.size();
    for (const Occurrence& run : runs.at(id)) {
      clips.push_back(TaggedClip{id, animate_clip(leaf, run, underneath.value_at(leaf.target, run.begin))});
    }
    for (std::size_t i = first; i < clips.size(); ++i) underneath.add(next++, clips[i].clip);
  }
}

}  // namespace

Timeline lower_to_timeline(const XmtoTree& tree, const Schedule& schedule) {
  std::vector<TaggedClip> clips;
  clips.reserve(schedule.occurrences.size());
  std::vector<AudioClip> audio;
  std::map<std::size_t, std::vector<Occurrence>> to_runs;
  for (const Occurrence& run : schedule.occurrences) {
    // A run cut to nothing (its parent ended first) contributes nothing, frozen or not.
    if (run.end <= run.begin) continue;
    const Leaf& leaf = tree.leaves[run.leaf_id];
    if (leaf.included) {
      place_included(leaf, run.leaf_id, run, clips, audio);
    } else if (leaf.function.to_animation) {
      to_runs[run.leaf_id].push_back(run);
    } else {
      clips.push_back(TaggedClip{run.leaf_id, animate_clip(leaf, run, 0)});
    }
  }
  place_to_animations(tree, to_runs, clips);
  // Document order of the elements, then time: the order overwrite ties are decided by. Runs come
  // in that order unless groups repeat or to-animations were placed: check before moving clips.
  const auto before = [](const TaggedClip& a, const TaggedClip& b) {
    return a.leaf != b.leaf ? a.leaf < b.leaf : a.clip.begin < b.clip.begin;
  };
  if (!std::is_sorted(clips.begin(), clips.end(), before)) std::stable_sort(clips.begin(), clips.end(), before);
  Timeline timeline;
  timeline.clips.reserve(clips.size());
  for (TaggedClip& tagged : clips) timeline.clips.push_back(std::move(tagged.clip));
  clips = {};
  timeline.audio = std::move(audio);
  timeline.explicit_end = schedule.end;
  timeline.end_source =
      end_source(schedule, tree.root.source, [&](std::size_t leaf) { return tree.leaves[leaf].where; });
  return timeline;
}

}  // namespace fapc::xmt

#include <algorithm>
#include <cstdint>
#include <set>
#include <span>
#include <string_view>

#include "fapc/transcoder/audio_mix.hpp"
#include "fapc/transcoder/growing_timeline.hpp"
#include "fapc/transcoder/render.hpp"
#include "xmto/xmto_tree.hpp"

namespace fapc::xmt {
namespace {

// The clips made so far and the leaf each comes from (for the order of the timeline), side by
// side: the clips then become the timeline's as they are, without a copy.
struct TaggedClips {
  std::vector<Clip> clips;
  // 32 bits hold every leaf number: a document is under 2 GiB (the XML parser's limit) and an
  // element takes more than one byte.
  std::vector<std::uint32_t> leaf;
  void add(std::size_t id, Clip clip) {
    clips.push_back(std::move(clip));
    leaf.push_back(static_cast<std::uint32_t>(id));
  }
  std::size_t size() const { return clips.size(); }
};

// Puts the clips in order of their leaf (document order), then begin, stably; in place (a copy of
// the clips would double the largest structure of the lowering).
void sort_by_leaf(TaggedClips& tagged) {
  const std::size_t n = tagged.size();
  const auto before = [&](std::size_t a, std::size_t b) {
    return tagged.leaf[a] != tagged.leaf[b] ? tagged.leaf[a] < tagged.leaf[b]
                                            : tagged.clips[a].begin < tagged.clips[b].begin;
  };
  bool sorted = true;
  for (std::size_t i = 1; i < n && sorted; ++i) sorted = !before(i, i - 1);
  if (sorted) return;
  // order[i]: the clip that goes to position i. Leaf numbers are dense: counted into their places
  // (stable), then each leaf's clips sorted by begin where they are not already.
  std::size_t leaves = 0;
  for (const std::size_t leaf : tagged.leaf) leaves = std::max(leaves, leaf + 1);
  // 32-bit positions: the clips are within the runs limit (fapc caps --max-runs at 2^30).
  std::vector<std::uint32_t> place(leaves + 1, 0);
  for (const std::size_t leaf : tagged.leaf) ++place[leaf + 1];
  for (std::size_t k = 1; k <= leaves; ++k) place[k] += place[k - 1];
  std::vector<std::uint32_t> order(n);
  {
    std::vector<std::uint32_t> next(place.begin(), place.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order[next[tagged.leaf[i]]++] = static_cast<std::uint32_t>(i);
  }
  for (std::size_t k = 0; k < leaves; ++k) {
    const auto from = order.begin() + static_cast<std::ptrdiff_t>(place[k]);
    const auto to = order.begin() + static_cast<std::ptrdiff_t>(place[k + 1]);
    if (!std::is_sorted(from, to, before)) std::stable_sort(from, to, before);
  }
  // Each cycle of the permutation is moved round once through one spare clip.
  for (std::size_t i = 0; i < n; ++i) {
    if (order[i] == i) continue;
    Clip spare = std::move(tagged.clips[i]);
    const std::uint32_t spare_leaf = tagged.leaf[i];
    std::size_t at = i;
    while (order[at] != i) {
      const std::size_t from = order[at];
      tagged.clips[at] = std::move(tagged.clips[from]);
      tagged.leaf[at] = tagged.leaf[from];
      order[at] = static_cast<std::uint32_t>(at);
      at = from;
    }
    tagged.clips[at] = std::move(spare);
    tagged.leaf[at] = spare_leaf;
    order[at] = static_cast<std::uint32_t>(at);
  }
}

// The included animation's clips and audio for one run: shifted to the run's begin, cut at its end.
void place_included(const Leaf& leaf, std::size_t id, const Occurrence& run, TaggedClips& out,
                    std::vector<AudioClip>& audio) {
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
    out.add(id, std::move(clip));
  }
}

Clip animate_clip(const XmtoTree& tree, const Leaf& leaf, const Occurrence& run, double underlying) {
  Clip clip;
  clip.target = tree.target(leaf);
  clip.begin = run.begin;
  clip.end = run.end;
  clip.curve_offset = run.curve_offset;
  clip.curve = animation_curve(leaf.function, tree.values(leaf), tree.key_times(leaf), underlying, run.iteration);
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
void place_to_animations(const XmtoTree& tree, const std::vector<Occurrence>& runs_in_schedule,
                         std::vector<std::size_t> to_runs, TaggedClips& clips) {
  if (to_runs.empty()) return;
  // `to_runs` (indices of the schedule's runs, in its order) grouped by element, each element's
  // runs kept in order; then the elements by their first begin (stable: document order at ties).
  const auto run = [&](std::size_t k) -> const Occurrence& { return runs_in_schedule[k]; };
  std::stable_sort(to_runs.begin(), to_runs.end(),
                   [&](std::size_t a, std::size_t b) { return run(a).leaf_id < run(b).leaf_id; });
  using Element = std::span<const std::size_t>;
  std::vector<Element> order;
  for (std::size_t from = 0, to = 0; from < to_runs.size(); from = to) {
    while (to < to_runs.size() && run(to_runs[to]).leaf_id == run(to_runs[from]).leaf_id) ++to;
    order.push_back(Element(to_runs).subspan(from, to - from));
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](Element a, Element b) { return run(a.front()).begin < run(b.front()).begin; });
  const auto leaf_of = [&](Element element) { return run(element.front()).leaf_id; };
  std::set<std::string_view> targets;
  for (const Element element : order) targets.insert(tree.target(tree.leaves[leaf_of(element)]));
  // Every clip the growing timeline will hold: those placed so far, then the runs in order.
  std::vector<PlannedClip> planned;
  std::vector<std::size_t> placed;  // indices into `clips` of the planned clips placed so far
  for (std::size_t i = 0; i < clips.size(); ++i) {
    if (!targets.contains(clips.clips[i].target)) continue;
    placed.push_back(i);
    planned.push_back({clips.clips[i].target, clips.clips[i].begin});
  }
  for (const Element element : order) {
    const TargetName target = tree.target(tree.leaves[leaf_of(element)]);
    for (const std::size_t k : element) planned.push_back({target, run(k).begin});
  }
  GrowingTimeline underneath(planned, clips.clips);
  std::size_t next = 0;
  for (const std::size_t i : placed) underneath.add(next++, i);
  for (const Element element : order) {
    const std::size_t id = leaf_of(element);
    const Leaf& leaf = tree.leaves[id];
    const std::size_t first = clips.size();
    for (const std::size_t k : element) {
      clips.add(id, animate_clip(tree, leaf, run(k), underneath.value_at(tree.target(leaf), run(k).begin)));
    }
    for (std::size_t i = first; i < clips.size(); ++i) underneath.add(next++, i);
  }
}

}  // namespace

Timeline lower_to_timeline(const XmtoTree& tree, const Schedule& schedule) {
  TaggedClips clips;
  clips.clips.reserve(schedule.occurrences.size());
  clips.leaf.reserve(schedule.occurrences.size());
  std::vector<AudioClip> audio;
  std::vector<std::size_t> to_runs;  // indices of the to-animations' runs
  for (const Occurrence& run : schedule.occurrences) {
    // A run cut to nothing (its parent ended first) contributes nothing, frozen or not.
    if (run.end <= run.begin) continue;
    const Leaf& leaf = tree.leaves[run.leaf_id];
    if (leaf.included) {
      place_included(leaf, run.leaf_id, run, clips, audio);
    } else if (leaf.function.to_animation) {
      to_runs.push_back(static_cast<std::size_t>(&run - schedule.occurrences.data()));
    } else {
      clips.add(run.leaf_id, animate_clip(tree, leaf, run, 0));
    }
  }
  place_to_animations(tree, schedule.occurrences, std::move(to_runs), clips);
  // Document order of the elements, then time: the order overwrite ties are decided by. Runs come
  // in that order unless groups repeat or to-animations were placed.
  sort_by_leaf(clips);
  Timeline timeline;
  timeline.clips = std::move(clips.clips);
  timeline.audio = std::move(audio);
  timeline.explicit_end = schedule.end;
  timeline.end_source = body_end_source(tree, schedule);
  return timeline;
}

Location body_end_source(const XmtoTree& tree, const Schedule& schedule) {
  return end_source(schedule, tree.root.source, [&](std::size_t leaf) { return tree.leaves[leaf].where; });
}

}  // namespace fapc::xmt

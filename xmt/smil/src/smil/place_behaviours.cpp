// Scheduled SMIL-Agent runs to one BML block (docs/smil.md, "Spans anchored to a speech"):
// speeches where the scheduler put them, anchored affects and actions at their speech's marks,
// every display fitted to its span with the onset and offset BML gives it by default
// (bml/behaviour_defaults.hpp).
#include <algorithm>

#include "bml/behaviour_defaults.hpp"
#include "fapc/smil/codes.hpp"
#include "smil/smil_script.hpp"

namespace fapc::smil {
namespace {

using Points = std::array<double, bml::kStandardPoints>;

// A display over [start, end]: its default onset to the peak, held, its default offset back; both
// shortened in proportion when the span is shorter than they are. A shift (fill="freeze") only
// rises, and holds from there on.
Points fitted(const bml::Behaviour& b, double start, double end) {
  const Points defaults = bml::default_offsets(b);
  const double length = end - start;
  double onset = defaults[bml::kReady];
  double offset = b.shift ? 0 : defaults[bml::kEnd] - defaults[bml::kRelax];
  // A head turn is a shift in BML (it has no return); one that does not freeze returns as it came.
  if (!b.shift && offset == 0) offset = onset;
  if (onset + offset > length && onset + offset > 0) {
    const double scale = length / (onset + offset);
    onset *= scale;
    offset *= scale;
  }
  if (b.shift) {
    const double peak = start + onset;
    return {start, peak, peak, peak, peak, peak, peak};
  }
  const double ready = start + onset;
  const double relax = end - offset;
  return {start, ready, ready, (ready + relax) / 2, relax, relax, end};
}

}  // namespace

Result<PlacedScript> place_behaviours(const std::vector<SmilLeaf>& leaves, const Schedule& schedule,
                                      std::int64_t max_runs, std::vector<PlacedBehaviour>& placed) {
  PlacedScript out;
  out.end = schedule.end;
  std::vector<std::vector<double>> speech_runs(leaves.size());
  std::int64_t spans = 0;
  auto add_span = [&](const SmilLeaf& leaf, double start, double end) -> Status {
    if (++spans > max_runs) {
      Limits limits;
      limits.max_runs = max_runs;
      return limit_error(leaf.where, "the script's affects and actions make too many spans", Limit::runs, limits);
    }
    placed.push_back({leaf.kind == SmilLeaf::Kind::affect ? "speech-animation" : "action", leaf.name, start, end,
                      !leaf.behaviours.empty()});
    for (const bml::Behaviour& shape : leaf.behaviours) {
      out.solution.points.push_back(fitted(shape, start, end));
      out.block.behaviours.push_back(shape);
    }
    if (end >= out.end) {
      out.end = end;
      out.end_source = leaf.where;
    }
    return ok_status();
  };
  for (const Occurrence& run : schedule.occurrences) {
    const SmilLeaf& leaf = leaves[run.leaf_id];
    if (leaf.kind == SmilLeaf::Kind::speech) {
      speech_runs[run.leaf_id].push_back(run.begin - run.curve_offset);
      bml::Behaviour b;
      b.kind = bml::BehaviourKind::speech;
      b.element = "speech";
      b.where = leaf.where;
      b.speech = std::make_unique<bml::SpokenText>(*leaf.spoken);
      const double begin = run.begin - run.curve_offset;
      const double d = leaf.spoken->duration;
      out.solution.points.push_back({begin, begin, begin, begin, begin + d, begin + d, begin + d});
      out.block.behaviours.push_back(std::move(b));
      if (begin + d >= out.end) {
        out.end = begin + d;
        out.end_source = leaf.where;
      }
    } else if (!leaf.speech) {
      if (run.end > run.begin)
        if (Status s = add_span(leaf, run.begin, run.end); !s) return s.error();
    }
  }
  for (const SmilLeaf& leaf : leaves) {
    if (!leaf.speech) continue;
    const bml::SpokenText& spoken = *leaves[*leaf.speech].spoken;
    const double from = (leaf.begin_mark ? spoken.mark_times[*leaf.begin_mark] : 0.0) + leaf.offset;
    const double to = leaf.end_mark   ? spoken.mark_times[*leaf.end_mark]
                      : leaf.duration ? from + *leaf.duration
                                      : spoken.duration;
    if (to <= from) {
      return make_error(codes::smil::empty_span, leaf.where,
                        "this span is empty: its content-end comes " +
                            std::string(to < from ? "before" : "at the same time as") +
                            " its content-begin in the speech as spoken");
    }
    for (double begin : speech_runs[*leaf.speech])
      if (Status s = add_span(leaf, begin + from, begin + to); !s) return s.error();
  }
  return out;
}

}  // namespace fapc::smil

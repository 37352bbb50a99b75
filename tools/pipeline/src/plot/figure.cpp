// Building the figure: the series a plot draws (docs/cli.md, "Plot").
#include "figure.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <optional>

#include "fapc/codec/fap_table.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/transcoder/algebra.hpp"
#include "fapc/transcoder/render.hpp"

namespace fapc::pipeline::plot {

namespace {

// The frames' values as series, one per FAP the frames carry, in one pass over the frames and
// each line thinned as it is read (column_picks.hpp): a long input never has its points held
// (docs/cli.md: a plot of 10^5 frames in well under a second, and in memory the plot's size).
std::vector<std::pair<std::string, Points>> series_from_frames(const FapSequence& sequence, double duration) {
  std::vector<ColumnPicks> by_fap(kFapCount + 1, ColumnPicks(duration));
  std::vector<bool> present(kFapCount + 1, false);
  for (const FapFrame& frame : sequence.frames) {
    const double t = static_cast<double>(frame.number) / sequence.fps;
    for (int fap = 1; fap <= kFapCount; ++fap) {
      if (!frame.has(fap)) continue;
      const double value = fap == 1 ? frame.viseme.select1 : fap == 2 ? frame.expression.select1 : frame.value(fap);
      by_fap[static_cast<std::size_t>(fap)].add(t, value);
      present[static_cast<std::size_t>(fap)] = true;
    }
  }
  std::vector<std::pair<std::string, Points>> out;
  for (int fap = 1; fap <= kFapCount; ++fap)
    if (present[static_cast<std::size_t>(fap)])
      out.emplace_back(std::string(find_fap(fap)->name), by_fap[static_cast<std::size_t>(fap)].take());
  return out;
}

// A script's curve as the panels show it.
Points visible_points(const Points& points, double duration) {
  ColumnPicks picks(duration);
  for (const auto& [t, v] : points) picks.add(t, v);
  return picks.take();
}

bool zero_throughout(const Points& points) {
  return std::all_of(points.begin(), points.end(), [](const auto& p) { return p.second == 0; });
}

std::string trimmed(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return std::string(text);
}

// The FAP names one selection item stands for: a FAP, a range or a group (the Algebra's mask
// syntax, docs/algebra.md), or viseme/expression by name or number.
std::optional<std::vector<std::string>> fap_names_of(const std::string& item) {
  if (const FapInfo* fap = find_fap_by_name_or_number(item); fap && fap->number <= 2)
    return std::vector<std::string>{std::string(fap->name)};
  auto mask = algebra::parse_mask(item);
  if (!mask) return std::nullopt;
  std::vector<std::string> names;
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (mask->covers(fap)) names.emplace_back(find_fap(fap)->name);
  return names;
}

}  // namespace

int target_order(const std::string& name) {
  const FapInfo* fap = find_fap(name);
  return fap ? fap->number : INT_MAX;
}

std::string target_unit(const std::string& name) {
  const FapInfo* fap = find_fap(name);
  if (!fap) return "";
  if (fap->number <= 2) return "number";
  return std::string(fapu_name(fap->unit));
}

Result<std::vector<std::string>> select_targets(const std::string& selection, const std::vector<std::string>& available,
                                                const std::string& input) {
  if (trimmed(selection).empty()) return available;
  std::vector<std::string> wanted;
  std::size_t start = 0;
  while (start <= selection.size()) {
    const std::size_t comma = std::min(selection.find(',', start), selection.size());
    const std::string item = trimmed(std::string_view(selection).substr(start, comma - start));
    start = comma + 1;
    if (item.empty()) continue;
    if (std::find(available.begin(), available.end(), item) != available.end()) {
      wanted.push_back(item);
      continue;
    }
    const auto names = fap_names_of(item);
    if (!names) {
      std::string message = "--faps: unknown parameter or group '" + item + "'";
      // The closest spelling among groups, FAP names and the input's own targets.
      std::vector<std::string> candidates = available;
      for (const auto& group : algebra::mask_group_names()) candidates.emplace_back(group.first);
      for (const FapInfo& fap : fap_table()) candidates.emplace_back(fap.name);
      std::string best;
      std::size_t best_distance = 3;  // farther than two edits is no suggestion
      for (const std::string& candidate : candidates)
        if (const std::size_t d = edit_distance(item, candidate); d < best_distance) {
          best = candidate;
          best_distance = d;
        }
      if (!best.empty()) message += "; did you mean " + best + "?";
      message +=
          " (a FAP name or number, a range like 19-30, a group: jaw, lips, eyes, brows, cheeks, "
          "tongue, head, outer_lips, nose, ears, mouth, all; or viseme, expression)";
      return make_error(codes::plot::unknown_parameter, Location::whole_file(input), message);
    }
    wanted.insert(wanted.end(), names->begin(), names->end());
  }
  std::vector<std::string> chosen;
  for (const std::string& name : available)
    if (std::find(wanted.begin(), wanted.end(), name) != wanted.end()) chosen.push_back(name);
  if (chosen.empty()) {
    std::string has;
    for (const std::string& name : available) has += (has.empty() ? "" : ", ") + name;
    return make_error(codes::plot::nothing_selected, Location::whole_file(input),
                      "--faps '" + selection +
                          "' selects none of this input's parameters (it has: " + (has.empty() ? "none" : has) + ")");
  }
  return chosen;
}

Result<Figure> build_figure(const Loaded& loaded, const std::string& input, const PlotOptions& options) {
  Figure figure;
  figure.title = options.title;
  figure.overlay = options.overlay;
  std::vector<std::pair<std::string, Points>> blended;
  if (loaded.curves) {
    figure.duration = loaded.curves->duration;
    for (const auto& [name, points] : loaded.curves->curves)
      blended.emplace_back(name, visible_points(points, figure.duration));
  } else {
    figure.duration = loaded.frames.duration_seconds();
    blended = series_from_frames(loaded.frames, figure.duration);
  }
  std::stable_sort(blended.begin(), blended.end(),
                   [](const auto& a, const auto& b) { return target_order(a.first) < target_order(b.first); });

  std::optional<Curves> clips;
  if (options.per_clip) {
    if (!loaded.timeline)
      return make_error(codes::plot::per_clip_needs_timeline, Location::whole_file(input),
                        "--per-clip needs a timeline input (Mimic, FML or XMT-Omega); this input has frames only");
    clips = render_clip_curves(*loaded.timeline, CurveOptions{options.fps, 1e-6});
  }

  std::vector<std::string> available;
  for (const auto& entry : blended) available.push_back(entry.first);
  auto chosen = select_targets(options.faps, available, input);
  if (!chosen) return chosen.error();

  for (auto& [name, points] : blended) {
    if (std::find(chosen->begin(), chosen->end(), name) == chosen->end()) continue;
    Series series{name, target_unit(name), target_order(name), std::move(points), {}};
    bool all_zero = zero_throughout(series.points);
    if (clips) {
      // "jaw (table2.mimic:5) #2": the clips of this target, labelled by their line number.
      const std::string prefix = name + " (";
      for (const auto& [key, clip_points] : clips->curves) {
        if (!key.starts_with(prefix)) continue;
        const auto colon = key.rfind(':');
        const auto close = key.find(')', colon == std::string::npos ? 0 : colon);
        const std::string label =
            colon == std::string::npos || close == std::string::npos ? key : key.substr(colon + 1, close - colon - 1);
        series.clips.emplace_back(label, visible_points(clip_points, figure.duration));
        all_zero = all_zero && zero_throughout(clip_points);
      }
    }
    if (all_zero) {
      figure.omitted.push_back(name);
    } else {
      figure.series.push_back(std::move(series));
    }
  }
  return figure;
}

}  // namespace fapc::pipeline::plot

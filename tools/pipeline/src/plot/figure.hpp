// What a plot shows, before it is drawn: the series in FAP order with their units, grouped into
// panels, and what was left out. Built once from the input; every output format reads it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "column_picks.hpp"
#include "fapc/pipeline/plot.hpp"

namespace fapc::pipeline::plot {

struct Series {
  std::string name;  // target name: "open_jaw", "viseme", a free parameter
  std::string unit;  // "MNS", "AU"... (docs/fap-table.md), "number" for viseme/expression, "" otherwise
  int order = 0;     // FAP number; targets that are not FAPs come after, by name
  Points points;     // only what the panels can show of it (column_picks.hpp), when the figure has a duration
  // Each clip's own curve for this target (--per-clip), labelled by its source line.
  std::vector<std::pair<std::string, Points>> clips;
};

struct Figure {
  std::string title;
  double duration = 0;               // seconds: the shared time axis runs 0..duration
  bool overlay = false;              // one panel for every series, with a legend
  std::vector<Series> series;        // drawn, in FAP order
  std::vector<std::string> omitted;  // zero throughout, in FAP order
};

// Order of a target: its FAP number (viseme 1, expression 2), else after every FAP.
int target_order(const std::string& name);
// Its unit as an axis title shows it.
std::string target_unit(const std::string& name);

// The targets `selection` names among `available` (PlotOptions::faps); empty selection: all.
Result<std::vector<std::string>> select_targets(const std::string& selection, const std::vector<std::string>& available,
                                                const std::string& input);

Result<Figure> build_figure(const Loaded& loaded, const std::string& input, const PlotOptions& options);

}  // namespace fapc::pipeline::plot

// `fapc plot`: curves as a figure for a paper, or as a table. One drawing routine draws every
// picture format: SVG (written as text, see docs/cli.md, "Plot"), PNG and PDF (cairo);
// `.csv` is the frames as a table for gnuplot or a spreadsheet.
#pragma once

#include <string>
#include <vector>

#include "fapc/pipeline/loaded.hpp"

namespace fapc::pipeline {

struct PlotOptions {
  std::string title;  // above the figure; empty: none
  // Which parameters: comma-separated FAP names or numbers, ranges ("19-30"), groups of the FAP
  // table ("lips", "jaw", "eyes", "brows", "mouth"..., docs/fap-table.md section 3), "viseme",
  // "expression", or any other target name of the input. Empty: every one.
  std::string faps;
  bool overlay = false;   // every parameter in one panel, with a legend
  bool per_clip = false;  // each clip's own curve under the blended one (timeline inputs only)
  int fps = 25;           // how per-clip curves are sampled
};

enum class PlotKind { svg, png, pdf, csv };

// By the output's extension (.svg, .png, .pdf, .csv); false when it is none of them.
bool plot_kind_for(const std::string& output, PlotKind& kind);

struct Plot {
  std::string bytes;
  // What a reader of the figure should know that it does not show, e.g. the parameters left out
  // because they are zero throughout (the figure says so too). The program prints them as notes.
  std::vector<std::string> notes;
};

// The input's curves (a script's own, or the frames') as `kind`. `input` names the loaded file in
// errors; usage errors for a selection that matches nothing or names no parameter.
Result<Plot> plot_loaded(const Loaded& loaded, const std::string& input, PlotKind kind, const PlotOptions& options);

}  // namespace fapc::pipeline

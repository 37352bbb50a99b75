// plot_loaded: the figure built once, then written in the format the output's name asks for.
#include "fapc/pipeline/plot.hpp"

#include <filesystem>

#include "canvas.hpp"
#include "csv.hpp"
#include "fapc/pipeline/codes.hpp"
#include "figure.hpp"

namespace fapc::pipeline {

bool plot_kind_for(const std::string& output, PlotKind& kind) {
  const std::string extension = std::filesystem::path(output).extension().string();
  if (extension == ".svg")
    kind = PlotKind::svg;
  else if (extension == ".png")
    kind = PlotKind::png;
  else if (extension == ".pdf")
    kind = PlotKind::pdf;
  else if (extension == ".csv")
    kind = PlotKind::csv;
  else
    return false;
  return true;
}

Result<Plot> plot_loaded(const Loaded& loaded, const std::string& input, PlotKind kind, const PlotOptions& options) {
  if (kind == PlotKind::csv) {
    auto csv = plot::frames_csv(loaded.frames, options.faps, input);
    if (!csv) return csv.error();
    return Plot{std::move(*csv), {}};
  }
  auto figure = plot::build_figure(loaded, input, options);
  if (!figure) return figure.error();
  Plot out;
  if (!figure->omitted.empty()) {
    std::string names;
    for (const std::string& name : figure->omitted) names += (names.empty() ? "" : ", ") + name;
    out.notes.push_back(std::to_string(figure->omitted.size()) + " parameter" +
                        (figure->omitted.size() == 1 ? "" : "s") + " not drawn, zero throughout: " + names);
  }
  switch (kind) {
    case PlotKind::svg:
      out.bytes = plot::svg_document(*figure);
      break;
    case PlotKind::png:
      out.bytes = plot::cairo_png(*figure, 2);
      break;  // 1920 pixels wide: print quality
    case PlotKind::pdf:
      out.bytes = plot::cairo_pdf(*figure);
      break;
    case PlotKind::csv:
      break;
  }
  if (out.bytes.empty())
    return make_error(codes::plot::draw_failed, Location::whole_file(input), "cairo could not draw the plot");
  return out;
}

}  // namespace fapc::pipeline

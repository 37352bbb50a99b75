// .svg, .pdf and .csv outputs of compile and batch: the plot of `fapc plot` with its defaults
// (every parameter, one panel each). A .png output is the face (format_face.cpp), not a plot.
#include <filesystem>

#include "fapc/pipeline/plot.hpp"
#include "formats.hpp"

namespace fapc::pipeline::builtin {

namespace {

// A .csv is the frames as a table (plot/csv.cpp); .svg and .pdf draw a script's curves, or the
// frames of an input without a timeline (plot/figure.cpp).
OutputFormat plot_output(std::string kind, std::string extension, PlotKind plot_kind) {
  const bool reads_frames = plot_kind == PlotKind::csv;
  return {std::move(kind),
          {std::move(extension)},
          [plot_kind](const Loaded& loaded, const std::string& path, const ConvertOptions&) -> Result<std::string> {
            PlotOptions options;
            options.title = std::filesystem::path(path).stem().string();
            auto plot = plot_loaded(loaded, loaded.named(path), plot_kind, options);
            if (!plot) return plot.error();
            return std::move(plot->bytes);
          },
          /*uses_curves=*/!reads_frames,
          /*uses_frames=*/reads_frames};
}

}  // namespace

OutputFormat svg_output() { return plot_output("svg", ".svg", PlotKind::svg); }
OutputFormat pdf_output() { return plot_output("pdf", ".pdf", PlotKind::pdf); }
OutputFormat csv_output() { return plot_output("csv", ".csv", PlotKind::csv); }

}  // namespace fapc::pipeline::builtin

// .svg output: the blended curves plotted (`fapc plot` adds the per-clip curves).
#include <filesystem>

#include "fapc/pipeline/svg_plot.hpp"
#include "formats.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<std::string> write_svg(const Loaded& loaded, const std::string& path, const ConvertOptions&) {
  const Curves curves = loaded.curves ? *loaded.curves : curves_from_frames(loaded.frames);
  return plot_svg(curves, nullptr, std::filesystem::path(path).stem().string());
}

}  // namespace

OutputFormat svg_output() { return {"svg", {".svg"}, write_svg, true}; }

}  // namespace fapc::pipeline::builtin

// .svg output: the blended curves plotted (`fapc plot` adds the per-clip curves).
#include <filesystem>

#include "fapc/registry.hpp"
#include "fapc/svg_plot.hpp"

namespace fapc::cli {

namespace {

Result<std::string> write_svg(const Loaded& loaded, const std::string& path, const ConvertOptions&) {
  const Curves curves = loaded.curves ? *loaded.curves : curves_from_frames(loaded.frames);
  return plot_svg(curves, nullptr, std::filesystem::path(path).stem().string());
}

const RegisterOutput svg_output{OutputFormat{"svg", {".svg"}, write_svg}};

}  // namespace

}  // namespace fapc::cli

// Curves as an SVG figure: one panel per target on a shared time axis. With per-clip curves, each
// panel also draws every clip's own curve, labelled by its source line, under the blended one
// (the two halves of Mimic Figure 1 in one picture; docs/mimic.md).
#pragma once

#include <string>

#include "fapc/transcoder/curves.hpp"

namespace fapc::cli {

std::string plot_svg(const Curves& blended, const Curves* per_clip, const std::string& title);

}  // namespace fapc::cli

// Curves as an SVG figure: one panel per target on a shared time axis. With per-clip curves, each
// panel also draws every clip's own curve, labelled by its source line, under the blended one
// (the two halves of Mimic Figure 1 in one picture; docs/mimic.md).
#pragma once

#include <string>

#include "fapc/pipeline/loaded.hpp"
#include "fapc/transcoder/curves.hpp"

namespace fapc::pipeline {

std::string plot_svg(const Curves& blended, const Curves* per_clip, const std::string& title);

// `fapc plot`: the input's curves (a script's own, or the frames'), and with `per_clip` every
// clip's curve sampled at `fps` (unsupported without a timeline). `input` names the loaded file
// in errors.
Result<std::string> plot_loaded(const Loaded& loaded, const std::string& input, const std::string& title,
                                bool per_clip, int fps);

}  // namespace fapc::pipeline

// The preview page's 3D view: a canvas, three.js with its licence, the page's .glb as base64, and
// the script that plays it at the time the page's clock shows (docs/render.md, "The 3D view").
#pragma once

#include <string>

#include "fapc/face/preview_page.hpp"

namespace fapc::face {

// The HTML to put before the page's own script: it defines window.fapcHead3d = {loaded, show(t)}.
std::string head3d_view(const PreviewOptions& options);

}  // namespace fapc::face

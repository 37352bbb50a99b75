// A seven-segment stroke font for the few characters pictures carry (time stamps, feature point
// numbers): digits, '.', '-', 's'. Drawn as cairo strokes, not with a system font, so pictures
// come out the same on every machine and golden images stay exact.
#pragma once

#include <cairo.h>

#include <string_view>

namespace fapc::face {

// Adds the strokes of `text` to the current path, its top-left corner at (x, y), digits h high,
// and returns the x where the next character would start. The caller strokes.
double stroke_text(cairo_t* cr, std::string_view text, double x, double y, double h);

}  // namespace fapc::face

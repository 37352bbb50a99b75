// The few drawing operations a plot needs, in pixels from the top left. draw.cpp lays the figure
// out once against this; svg_canvas.cpp writes the operations as SVG text and cairo_canvas.cpp
// paints them with cairo (PNG and PDF surfaces). Colours are "#rrggbb".
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fapc::pipeline::plot {

using Pixels = std::vector<std::pair<double, double>>;

enum class Anchor { start, middle, end };

struct TextStyle {
  double size = 11;
  bool bold = false;
  Anchor anchor = Anchor::start;
  std::string_view colour = "#000000";
  bool vertical = false;  // turned a quarter anticlockwise about (x, y): a y-axis title
};

class Canvas {
 public:
  virtual ~Canvas() = default;
  virtual void rect(double x, double y, double width, double height, std::string_view stroke) = 0;
  virtual void line(double x1, double y1, double x2, double y2, std::string_view colour, double width) = 0;
  virtual void polyline(const Pixels& points, std::string_view colour, double width) = 0;
  virtual void dot(double x, double y, double radius, std::string_view colour) = 0;
  virtual void text(double x, double y, std::string_view text, const TextStyle& style) = 0;
};

struct Size {
  double width = 0;
  double height = 0;
};

struct Figure;
// How big `figure` is drawn, then the drawing itself: the one routine for every format.
Size figure_size(const Figure& figure);
void draw(const Figure& figure, Canvas& canvas);

// The SVG of `figure` (written as text: numbers by std::to_chars, text stays text).
std::string svg_document(const Figure& figure);
// PNG (at `scale` pixels per unit) or PDF bytes of `figure`, painted by cairo; empty on a cairo failure.
std::string cairo_png(const Figure& figure, double scale);
std::string cairo_pdf(const Figure& figure);

}  // namespace fapc::pipeline::plot

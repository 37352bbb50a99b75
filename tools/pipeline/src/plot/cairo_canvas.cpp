// The plot painted by cairo: PNG (an image surface) and PDF (a vector surface), from the same
// drawing routine as the SVG (draw.cpp).
#include <cairo-pdf.h>
#include <cairo.h>

#include <charconv>
#include <cmath>

#include "canvas.hpp"
#include "figure.hpp"

namespace fapc::pipeline::plot {

namespace {

void set_colour(cairo_t* cr, std::string_view hex) {
  unsigned value = 0;
  std::from_chars(hex.data() + 1, hex.data() + hex.size(), value, 16);
  cairo_set_source_rgb(cr, ((value >> 16) & 0xff) / 255.0, ((value >> 8) & 0xff) / 255.0, (value & 0xff) / 255.0);
}

class CairoCanvas final : public Canvas {
 public:
  explicit CairoCanvas(cairo_t* cr) : cr_(cr) {
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  }

  void rect(double x, double y, double width, double height, std::string_view stroke) override {
    cairo_rectangle(cr_, x, y, width, height);
    stroke_with(stroke, 1);
  }
  void line(double x1, double y1, double x2, double y2, std::string_view colour, double width) override {
    cairo_move_to(cr_, x1, y1);
    cairo_line_to(cr_, x2, y2);
    stroke_with(colour, width);
  }
  void polyline(const Pixels& points, std::string_view colour, double width) override {
    if (points.empty()) return;
    cairo_move_to(cr_, points[0].first, points[0].second);
    for (std::size_t k = 1; k < points.size(); ++k) cairo_line_to(cr_, points[k].first, points[k].second);
    cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
    stroke_with(colour, width);
  }
  void dot(double x, double y, double radius, std::string_view colour) override {
    cairo_new_sub_path(cr_);
    cairo_arc(cr_, x, y, radius, 0, 2 * M_PI);
    set_colour(cr_, colour);
    cairo_fill(cr_);
  }
  void text(double x, double y, std::string_view text, const TextStyle& style) override {
    const std::string s(text);
    cairo_save(cr_);
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           style.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_, style.size);
    cairo_text_extents_t extents;
    cairo_text_extents(cr_, s.c_str(), &extents);
    const double shift = style.anchor == Anchor::start    ? 0
                         : style.anchor == Anchor::middle ? extents.x_advance / 2
                                                          : extents.x_advance;
    cairo_translate(cr_, x, y);
    if (style.vertical) cairo_rotate(cr_, -M_PI / 2);
    cairo_move_to(cr_, -shift, 0);
    set_colour(cr_, style.colour);
    cairo_show_text(cr_, s.c_str());
    cairo_restore(cr_);
  }

 private:
  void stroke_with(std::string_view colour, double width) {
    set_colour(cr_, colour);
    cairo_set_line_width(cr_, width);
    cairo_stroke(cr_);
  }
  cairo_t* cr_;
};

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void paint(cairo_surface_t* surface, const Figure& figure, double scale) {
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, scale, scale);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  CairoCanvas canvas(cr);
  draw(figure, canvas);
  cairo_destroy(cr);
}

}  // namespace

std::string cairo_png(const Figure& figure, double scale) {
  const Size size = figure_size(figure);
  cairo_surface_t* surface =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(std::ceil(size.width * scale)),
                                 static_cast<int>(std::ceil(size.height * scale)));
  std::string out;
  if (cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS) {
    paint(surface, figure, scale);
    if (cairo_surface_write_to_png_stream(surface, append, &out) != CAIRO_STATUS_SUCCESS) out.clear();
  }
  cairo_surface_destroy(surface);
  return out;
}

std::string cairo_pdf(const Figure& figure) {
  const Size size = figure_size(figure);
  std::string out;
  // Points: the figure's pixels at 72 per inch, a 960-pixel figure 33.9 cm wide (scaled in the paper).
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(append, &out, size.width, size.height);
  if (cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS) {
    // No creation date: the same figure makes the same bytes (cairo stamps the clock otherwise,
    // and two writes a second apart differed).
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, "");
    paint(surface, figure, 1);
  }
  cairo_surface_finish(surface);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) out.clear();
  cairo_surface_destroy(surface);
  return out;
}

}  // namespace fapc::pipeline::plot

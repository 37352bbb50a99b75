#include "fapc/face/pictures.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fapc/face/codes.hpp"
#include "fapc/face/renderer.hpp"
#include "stroke_text.hpp"

namespace fapc::face {

namespace {

// "12.40s" at (x, y), digit height h, in the stroke font (stroke_text.hpp).
void stamp(cairo_t* cr, double seconds, double x, double y, double h) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2fs", seconds);
  cairo_set_line_width(cr, std::max(1.0, h / 8));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  stroke_text(cr, text, x, y, h);
  cairo_stroke(cr);
}

}  // namespace

Status check_picture_options(const PictureOptions& o, const std::string& where) {
  const Location at = Location::whole_file(where);
  if (o.width < kMinSide || o.height < kMinSide || o.width > kMaxSide || o.height > kMaxSide)
    return make_error(codes::picture::bad_size, at,
                      "--size " + std::to_string(o.width) + "x" + std::to_string(o.height) + ": each side must be " +
                          std::to_string(kMinSide) + " to " + std::to_string(kMaxSide) + " pixels");
  const std::string size = std::to_string(o.width) + "x" + std::to_string(o.height);
  if (std::int64_t{o.width} * o.height > o.limits.max_frame_pixels)
    return limit_error(
        at, "--size " + size + " is " + std::to_string(std::int64_t{o.width} * o.height) + " pixels a picture",
        Limit::frame_pixels, o.limits);
  if (o.frame && o.time) return make_error(codes::picture::conflicting_options, at, "give --frame or --time, not both");
  if (o.sheet && (o.frame || o.time))
    return make_error(codes::picture::conflicting_options, at, "--sheet picks its own frames; drop --frame/--time");
  if (o.frame && *o.frame < 0) return make_error(codes::picture::bad_frame, at, "--frame must be 0 or more");
  if (o.time && !(*o.time >= 0)) return make_error(codes::picture::bad_frame, at, "--time must be 0 or more seconds");
  if (o.sheet && (*o.sheet < 1 || *o.sheet > kMaxSheetFrames))
    return make_error(
        codes::picture::sheet_cells, at,
        "--sheet " + std::to_string(*o.sheet) + ": a sheet holds 1 to " + std::to_string(kMaxSheetFrames) + " frames");
  if (o.sheet) {
    const int columns = static_cast<int>(std::ceil(std::sqrt(double(*o.sheet))));
    const int rows = (*o.sheet + columns - 1) / columns;
    if (std::int64_t(columns) * o.width > 16384 || std::int64_t(rows) * o.height > 16384)
      return make_error(codes::picture::sheet_too_wide, at,
                        "a contact sheet of " + std::to_string(*o.sheet) + " cells at --size " +
                            std::to_string(o.width) + "x" + std::to_string(o.height) +
                            " would pass 16384 pixels on a side; use a smaller --size");
    const std::int64_t pixels = std::int64_t{columns} * o.width * rows * o.height;
    if (pixels > o.limits.max_sheet_pixels)
      return limit_error(at,
                         "a contact sheet of " + std::to_string(*o.sheet) + " cells at --size " + size + " is " +
                             std::to_string(pixels) + " pixels",
                         Limit::sheet_pixels, o.limits);
  }
  return ok_status();
}

std::vector<double> sheet_times(const FaceTrack& track, int cells) {
  std::vector<double> times;
  const double last = track.frame_count() > 0 ? double(track.frame_count() - 1) / track.fps() : 0;
  for (int i = 0; i < cells; ++i) {
    // Each instant snapped to the start of its frame, so the stamp says what is shown.
    const double t = cells > 1 ? last * i / (cells - 1) : 0;
    times.push_back(std::floor(t * track.fps() + 1e-6) / track.fps());
  }
  return times;
}

Result<Image> render_picture(const FaceTrack& track, const PictureOptions& o, const std::string& where) {
  if (Status checked = check_picture_options(o, where); !checked) return checked.error();
  FaceRenderer renderer(o.width, o.height);
  renderer.show_feature_points(o.points);
  if (!o.sheet) {
    const FapValues& values = o.frame ? track.at_frame(*o.frame) : track.at_time(o.time.value_or(0));
    return renderer.render(values);
  }
  const int cells = *o.sheet;
  const int columns = static_cast<int>(std::ceil(std::sqrt(double(cells))));
  const int rows = (cells + columns - 1) / columns;
  Image sheet(columns * o.width, rows * o.height);
  cairo_surface_t* surface =
      cairo_image_surface_create_for_data(reinterpret_cast<unsigned char*>(sheet.pixels.data()), CAIRO_FORMAT_ARGB32,
                                          sheet.width, sheet.height, sheet.width * 4);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const std::vector<double> times = sheet_times(track, cells);
  const double digit = std::max(8.0, o.height / 16.0);
  for (int i = 0; i < cells; ++i) {
    const Image& frame = renderer.render(track.at_time(times[static_cast<std::size_t>(i)]));
    const int x0 = (i % columns) * o.width, y0 = (i / columns) * o.height;
    for (int y = 0; y < o.height; ++y)
      std::copy_n(frame.pixels.begin() + static_cast<std::ptrdiff_t>(y) * o.width, o.width,
                  sheet.pixels.begin() + static_cast<std::ptrdiff_t>(y0 + y) * sheet.width + x0);
    cairo_surface_mark_dirty(surface);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.15);
    stamp(cr, times[static_cast<std::size_t>(i)], x0 + digit / 2, y0 + digit / 2, digit);
    // A thin frame between cells.
    cairo_set_source_rgb(cr, 0.6, 0.62, 0.66);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, x0 + 0.5, y0 + 0.5, o.width - 1, o.height - 1);
    cairo_stroke(cr);
  }
  cairo_surface_flush(surface);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return sheet;
}

Result<std::string> face_png(const FapSequence& sequence, const PictureOptions& options, const std::string& where) {
  Result<Image> picture = render_picture(FaceTrack(sequence), options, where);
  if (!picture) return picture.error();
  return encode_png(*picture);
}

}  // namespace fapc::face

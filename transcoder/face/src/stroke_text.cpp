#include "stroke_text.hpp"

namespace fapc::face {

namespace {

//  bits: 0 top, 1 upper right, 2 lower right, 3 bottom, 4 lower left, 5 upper left, 6 middle
constexpr unsigned char kDigitSegments[10] = {0x3f, 0x06, 0x5b, 0x4f, 0x66, 0x6d, 0x7d, 0x07, 0x7f, 0x6f};

void segments(cairo_t* cr, unsigned char bits, double x, double y, double w, double h) {
  const double s[7][4] = {{0, 0, w, 0},     {w, 0, w, h / 2}, {w, h / 2, w, h},    {0, h, w, h},
                          {0, h / 2, 0, h}, {0, 0, 0, h / 2}, {0, h / 2, w, h / 2}};
  for (int i = 0; i < 7; ++i)
    if (bits & (1 << i)) {
      cairo_move_to(cr, x + s[i][0], y + s[i][1]);
      cairo_line_to(cr, x + s[i][2], y + s[i][3]);
    }
}

}  // namespace

double stroke_text(cairo_t* cr, std::string_view text, double x, double y, double h) {
  const double w = h / 2, gap = h / 3;
  for (char c : text) {
    if (c == '1') {  // the one is narrow: its segments on the left edge of a thin cell
      segments(cr, 0x30, x, y, w, h);
      x += gap * 1.5;
    } else if (c >= '0' && c <= '9') {
      segments(cr, kDigitSegments[c - '0'], x, y, w, h);
      x += w + gap;
    } else if (c == '.') {
      cairo_move_to(cr, x, y + h);
      cairo_line_to(cr, x, y + h);
      x += gap * 1.5;
    } else if (c == 's') {  // a small s: the 5's shape at half height
      segments(cr, kDigitSegments[5], x, y + h / 2, w * 0.8, h / 2);
      x += w + gap;
    } else if (c == '-') {
      segments(cr, 0x40, x, y, w, h);
      x += w + gap;
    } else {
      x += w + gap;  // anything else: a space
    }
  }
  return x;
}

}  // namespace fapc::face

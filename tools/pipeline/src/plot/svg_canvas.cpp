// The plot as SVG text. Written by hand rather than through cairo's SVG surface, which turns every
// letter into a path: here text stays text (searchable, editable, small), the bytes do not depend
// on the fonts installed (golden files compare exactly) and a number costs one std::to_chars.
#include <charconv>
#include <cmath>

#include "canvas.hpp"
#include "fapc/codec/xml_escape.hpp"
#include "figure.hpp"

namespace fapc::pipeline::plot {

namespace {

class SvgCanvas final : public Canvas {
 public:
  explicit SvgCanvas(std::string& out) : out_(out) {}

  void rect(double x, double y, double width, double height, std::string_view stroke) override {
    out_ += "<rect x=\"";
    number(x), out_ += "\" y=\"", number(y), out_ += "\" width=\"", number(width), out_ += "\" height=\"";
    number(height), out_ += "\" fill=\"none\" stroke=\"", out_ += stroke, out_ += "\"/>\n";
  }
  void line(double x1, double y1, double x2, double y2, std::string_view colour, double width) override {
    out_ += "<line x1=\"";
    number(x1), out_ += "\" y1=\"", number(y1), out_ += "\" x2=\"", number(x2), out_ += "\" y2=\"", number(y2);
    out_ += "\" stroke=\"", out_ += colour, out_ += "\" stroke-width=\"", number(width), out_ += "\"/>\n";
  }
  void polyline(const Pixels& points, std::string_view colour, double width) override {
    out_ += "<polyline fill=\"none\" stroke=\"", out_ += colour, out_ += "\" stroke-width=\"", number(width);
    out_ += "\" stroke-linejoin=\"round\" points=\"";
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (k) out_ += ' ';
      number(points[k].first), out_ += ',', number(points[k].second);
    }
    out_ += "\"/>\n";
  }
  void dot(double x, double y, double radius, std::string_view colour) override {
    out_ += "<circle cx=\"";
    number(x), out_ += "\" cy=\"", number(y), out_ += "\" r=\"", number(radius), out_ += "\" fill=\"", out_ += colour;
    out_ += "\"/>\n";
  }
  void text(double x, double y, std::string_view text, const TextStyle& style) override {
    out_ += "<text x=\"";
    number(x), out_ += "\" y=\"", number(y), out_ += '"';
    if (style.size != 11) out_ += " font-size=\"", number(style.size), out_ += '"';
    if (style.bold) out_ += " font-weight=\"bold\"";
    if (style.anchor == Anchor::middle) out_ += " text-anchor=\"middle\"";
    if (style.anchor == Anchor::end) out_ += " text-anchor=\"end\"";
    if (style.colour != "#000000") out_ += " fill=\"", out_ += style.colour, out_ += '"';
    if (style.vertical) out_ += " transform=\"rotate(-90 ", number(x), out_ += ' ', number(y), out_ += ")\"";
    out_ += '>', out_ += xml_escape(text), out_ += "</text>\n";
  }

  // Two decimals at most, trailing zeros dropped: a hundredth of a pixel is below what any
  // viewer shows.
  void number(double v) {
    v = std::round(v * 100) / 100;
    if (v == 0) v = 0;  // no "-0"
    char text[64];
    char* end = std::to_chars(text, text + sizeof text, v, std::chars_format::fixed, 2).ptr;
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
    out_.append(text, end);
  }

 private:
  std::string& out_;
};

}  // namespace

std::string svg_document(const Figure& figure) {
  const Size size = figure_size(figure);
  std::string out;
  SvgCanvas canvas(out);
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  canvas.number(size.width), out += "\" height=\"", canvas.number(size.height);
  out += "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  draw(figure, canvas);
  out += "</svg>\n";
  return out;
}

}  // namespace fapc::pipeline::plot

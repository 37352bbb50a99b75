#include "fapc/pipeline/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fapc/transcoder/render.hpp"
#include "xml_text.hpp"

namespace fapc::pipeline {

namespace {

constexpr double kWidth = 960;
constexpr double kLeft = 80;
constexpr double kRight = 20;
constexpr double kPanel = 150;
constexpr double kGap = 40;
constexpr double kTop = 40;
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

using Points = std::vector<std::pair<double, double>>;


// A round tick step giving about `count` ticks over `span`.
double tick_step(double span, int count) {
  if (span <= 0) return 1;
  const double raw = span / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * magnitude >= raw) return m * magnitude;
  }
  return 10 * magnitude;
}

struct Panel {
  double top;
  double low;
  double high;
  double duration;

  double x(double t) const { return kLeft + (kWidth - kLeft - kRight) * (duration > 0 ? t / duration : 0); }
  double y(double v) const { return top + kPanel - kPanel * (v - low) / (high - low); }
};

void polyline(std::ostringstream& svg, const Panel& panel, const Points& points,
              const char* colour, double width) {
  svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << width
      << "\" points=\"";
  for (const auto& [t, v] : points) svg << panel.x(t) << ',' << panel.y(v) << ' ';
  svg << "\"/>\n";
}

void axes(std::ostringstream& svg, const Panel& panel, const std::string& name) {
  svg << "<text x=\"" << kLeft << "\" y=\"" << panel.top - 6 << "\" font-weight=\"bold\">"
      << xml_escape(name) << "</text>\n";
  svg << "<rect x=\"" << kLeft << "\" y=\"" << panel.top << "\" width=\"" << kWidth - kLeft - kRight
      << "\" height=\"" << kPanel << "\" fill=\"none\" stroke=\"#999\"/>\n";
  for (const double v : {panel.low, panel.high}) {
    svg << "<text x=\"" << kLeft - 6 << "\" y=\"" << panel.y(v) + 4
        << "\" text-anchor=\"end\">" << v << "</text>\n";
  }
  const double step = tick_step(panel.duration, 10);
  for (double t = 0; t <= panel.duration + 1e-9; t += step) {
    svg << "<line x1=\"" << panel.x(t) << "\" x2=\"" << panel.x(t) << "\" y1=\"" << panel.top + kPanel
        << "\" y2=\"" << panel.top + kPanel + 4 << "\" stroke=\"#999\"/>"
        << "<text x=\"" << panel.x(t) << "\" y=\"" << panel.top + kPanel + 16
        << "\" text-anchor=\"middle\">" << t << "</text>\n";
  }
}

// "jaw (table2.mimic:5) #2" -> "5": the paper labels clip curves by their line number.
std::string line_label(const std::string& key) {
  const auto colon = key.rfind(':');
  const auto close = key.find(')', colon == std::string::npos ? 0 : colon);
  if (colon == std::string::npos || close == std::string::npos) return key;
  return key.substr(colon + 1, close - colon - 1);
}

}  // namespace

std::string plot_svg(const Curves& blended, const Curves* per_clip, const std::string& title) {
  const double height = kTop + static_cast<double>(blended.curves.size()) * (kPanel + kGap) + 10;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << kLeft << "\" y=\"20\" font-size=\"14\">" << xml_escape(title)
      << " (time in seconds)</text>\n";
  double top = kTop;
  std::size_t colour = 0;
  for (const auto& entry : blended.curves) {
    const std::string& target = entry.first;
    const Points& points = entry.second;  // not a binding: the lambda below captures it
    std::vector<const std::pair<const std::string, Points>*> clips;
    if (per_clip) {
      for (const auto& clip_entry : per_clip->curves) {
        if (clip_entry.first.starts_with(target + " (")) clips.push_back(&clip_entry);
      }
    }
    Panel panel{top, 0, 0, std::max(blended.duration, 1e-9)};
    for (const Points* list : [&] {
           std::vector<const Points*> all{&points};
           for (const auto* clip : clips) all.push_back(&clip->second);
           return all;
         }()) {
      for (const auto& [t, v] : *list) {
        panel.low = std::min(panel.low, v);
        panel.high = std::max(panel.high, v);
      }
    }
    if (panel.high <= panel.low) panel.high = panel.low + 1;
    axes(svg, panel, target);
    for (const auto* clip : clips) {
      polyline(svg, panel, clip->second, "#bbb", 1);
      if (!clip->second.empty()) {
        const auto& [t, v] = clip->second.front();
        svg << "<text x=\"" << panel.x(t) + 2 << "\" y=\"" << panel.y(v) - 3
            << "\" fill=\"#777\">" << xml_escape(line_label(clip->first)) << "</text>\n";
      }
    }
    polyline(svg, panel, points, kColours[colour++ % std::size(kColours)], 1.8);
    top += kPanel + kGap;
  }
  svg << "</svg>\n";
  return svg.str();
}

Result<std::string> plot_loaded(const Loaded& loaded, const std::string& input, const std::string& title,
                                bool per_clip, int fps) {
  std::optional<Curves> clips;
  if (per_clip) {
    if (!loaded.timeline)
      return make_error(ErrorKind::unsupported, Location{input, 0, 0, -1},
                        "--per-clip needs a timeline input (Mimic, FML or XMT-Omega); this input has frames only");
    clips = render_clip_curves(*loaded.timeline, CurveOptions{fps, 1e-6});
  }
  const Curves blended = loaded.curves ? *loaded.curves : curves_from_frames(loaded.frames);
  return plot_svg(blended, clips ? &*clips : nullptr, title);
}

}  // namespace fapc::pipeline

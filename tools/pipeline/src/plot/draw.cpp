// The one drawing routine of every plot format: panels in FAP order on a shared time axis (or one
// panel with a legend), axis titles with units, lines thinned to what a pixel column can show.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "canvas.hpp"
#include "column_picks.hpp"
#include "figure.hpp"
#include "plot_geometry.hpp"

namespace fapc::pipeline::plot {

namespace {

constexpr double kPanel = 150;  // height of a panel; an overlay panel is twice that
constexpr double kGap = 48;     // tick labels below a panel and the title of the next
constexpr double kLegendEntry = 220;
constexpr double kLine = 16;
constexpr std::size_t kWrap = 140;  // characters per line of the "not drawn" note
constexpr std::string_view kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                         "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
constexpr std::string_view kFrame = "#999999";
constexpr std::string_view kGrid = "#e6e6e6";
constexpr std::string_view kClip = "#bbbbbb";
constexpr std::string_view kNote = "#555555";

// A round step giving about `count` ticks over `span` (1, 2 or 5 times a power of ten).
double tick_step(double span, int count) {
  if (span <= 0) return 1;
  const double raw = span / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10 * magnitude;
}

// A tick value with as many decimals as its step needs ("0.2", not "0.20000000000000001").
std::string tick_text(double value, double step) {
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  if (std::abs(value) < step * 1e-6) value = 0;  // no "-0"
  char text[64];
  const auto end = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals).ptr;
  return std::string(text, end);
}

struct Layout {
  Size size;
  double top = 0;  // of the first panel
  double panel_height = kPanel;
  std::size_t panels = 0;
  double time_title_y = 0;  // "time (s)"
  double legend_y = 0;
  std::size_t legend_rows = 0;
  double note_y = 0;
  std::vector<std::string> note_lines;
};

std::vector<std::string> wrapped(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t next = text.find(' ', at);
    if (next == std::string::npos) next = text.size();
    const std::string word = text.substr(at, next - at);
    if (!line.empty() && line.size() + 1 + word.size() > kWrap) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    at = next + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

Layout layout(const Figure& figure) {
  Layout l;
  l.top = figure.title.empty() ? 24 : 48;
  if (figure.overlay) {
    l.panels = figure.series.empty() ? 0 : 1;
    l.panel_height = 2 * kPanel;
  } else {
    l.panels = figure.series.size();
  }
  double y = l.panels > 0 ? l.top + static_cast<double>(l.panels) * (l.panel_height + kGap) - kGap : l.top - 20;
  if (l.panels > 0) {
    l.time_title_y = y + 34;
    y = l.time_title_y + 8;
  }
  if (figure.overlay && !figure.series.empty()) {
    const auto per_row = static_cast<std::size_t>((kWidth - kLeft - kRight) / kLegendEntry);
    l.legend_rows = (figure.series.size() + per_row - 1) / per_row;
    l.legend_y = y + kLine;
    y += static_cast<double>(l.legend_rows) * kLine + 8;
  }
  if (!figure.omitted.empty()) {
    std::string note = "Not drawn, zero throughout:";
    for (std::size_t k = 0; k < figure.omitted.size(); ++k) note += (k ? ", " : " ") + figure.omitted[k];
    l.note_lines = wrapped(note);
    l.note_y = y + kLine;
    y += static_cast<double>(l.note_lines.size()) * kLine + 8;
  }
  l.size = {kWidth, std::ceil(y + 12)};
  return l;
}

// One panel's mapping from (seconds, value) to pixels.
struct Panel {
  double top = 0;
  double height = kPanel;
  double duration = 1;
  double low = 0;
  double high = 1;
  double step = 1;  // between value ticks

  double x(double t) const { return time_to_x(t, duration); }
  double y(double v) const { return top + height - height * (v - low) / (high - low); }
};

Panel panel_for(double top, double height, double duration, const std::vector<const Points*>& lists) {
  Panel panel{top, height, duration > 0 ? duration : 1, 0, 0, 1};
  for (const Points* list : lists)
    for (const auto& point : *list) {
      panel.low = std::min(panel.low, point.second);
      panel.high = std::max(panel.high, point.second);
    }
  if (panel.high <= panel.low) panel.high = panel.low + 1;
  panel.step = tick_step(panel.high - panel.low, 4);
  panel.low = std::floor(panel.low / panel.step - 1e-9) * panel.step;
  panel.high = std::ceil(panel.high / panel.step + 1e-9) * panel.step;
  return panel;
}

// Per pixel column only what a reader can see there (column_picks.hpp), so that a line of 10^6
// points in an 860-pixel panel costs a few thousand.
Pixels thinned(const Points& points, const Panel& panel) {
  ColumnPicks picks(panel.duration);
  for (const auto& [t, v] : points) picks.add(t, v);
  Pixels out;
  for (const auto& [t, v] : picks.take()) out.emplace_back(panel.x(t), panel.y(v));
  return out;
}

void series_line(Canvas& canvas, const Points& points, const Panel& panel, std::string_view colour, double width,
                 bool as_points) {
  if (as_points || points.size() < 2) {
    for (const auto& [t, v] : points) canvas.dot(panel.x(t), panel.y(v), 2.5, colour);
    return;
  }
  canvas.polyline(thinned(points, panel), colour, width);
}

std::string unit_title(const std::vector<const Series*>& series) {
  std::vector<std::string> units;
  for (const Series* s : series)
    if (!s->unit.empty() && std::find(units.begin(), units.end(), s->unit) == units.end()) units.push_back(s->unit);
  std::string title = "value";
  for (std::size_t k = 0; k < units.size(); ++k) title += (k ? ", " : " (") + units[k];
  return units.empty() ? title : title + ")";
}

void frame_and_axes(Canvas& canvas, const Panel& panel, const std::string& heading, const std::string& y_title) {
  const double right = kWidth - kRight;
  const TextStyle tick{10, false, Anchor::end, kNote, false};
  for (double v = panel.low; v <= panel.high + panel.step * 1e-6; v += panel.step) {
    canvas.line(kLeft, panel.y(v), right, panel.y(v), kGrid, 1);
    canvas.text(kLeft - 6, panel.y(v) + 3.5, tick_text(v, panel.step), tick);
  }
  const double time_step = tick_step(panel.duration, 10);
  const TextStyle time_tick{10, false, Anchor::middle, kNote, false};
  for (int k = 0; k * time_step <= panel.duration * (1 + 1e-9); ++k) {
    const double t = k * time_step;
    canvas.line(panel.x(t), panel.top + panel.height, panel.x(t), panel.top + panel.height + 4, kFrame, 1);
    canvas.text(panel.x(t), panel.top + panel.height + 16, tick_text(t, time_step), time_tick);
  }
  canvas.rect(kLeft, panel.top, right - kLeft, panel.height, kFrame);
  canvas.text(kLeft, panel.top - 7, heading, TextStyle{12, true, Anchor::start, "#000000", false});
  canvas.text(kLeft - 52, panel.top + panel.height / 2, y_title, TextStyle{11, false, Anchor::middle, "#000000", true});
}

std::string heading_of(const Series& series) {
  return series.order <= 68 ? series.name + " (FAP " + std::to_string(series.order) + ")" : series.name;
}

}  // namespace

Size figure_size(const Figure& figure) { return layout(figure).size; }

void draw(const Figure& figure, Canvas& canvas) {
  const Layout l = layout(figure);
  if (!figure.title.empty()) canvas.text(kLeft, 26, figure.title, TextStyle{15, true, Anchor::start, "#000000", false});
  const bool as_points = figure.duration <= 0;  // a single frame: points, no line
  double top = l.top;
  const auto draw_panel = [&](const std::vector<const Series*>& members, const std::string& heading) {
    std::vector<const Points*> lists;
    for (const Series* s : members) {
      lists.push_back(&s->points);
      for (const auto& clip : s->clips) lists.push_back(&clip.second);
    }
    const Panel panel = panel_for(top, l.panel_height, figure.duration, lists);
    frame_and_axes(canvas, panel, heading, unit_title(members));
    for (std::size_t k = 0; k < members.size(); ++k) {
      for (const auto& [label, points] : members[k]->clips) {
        series_line(canvas, points, panel, kClip, 1, as_points);
        if (!points.empty())
          canvas.text(panel.x(points.front().first) + 2, panel.y(points.front().second) - 3, label,
                      TextStyle{10, false, Anchor::start, "#777777", false});
      }
    }
    for (std::size_t k = 0; k < members.size(); ++k) {
      const std::size_t colour = figure.overlay ? k : static_cast<std::size_t>(&*members[k] - &figure.series[0]);
      series_line(canvas, members[k]->points, panel, kColours[colour % std::size(kColours)], 1.6, as_points);
    }
    top += l.panel_height + kGap;
  };
  if (figure.overlay && !figure.series.empty()) {
    std::vector<const Series*> all;
    for (const Series& s : figure.series) all.push_back(&s);
    draw_panel(all, figure.series.size() == 1 ? heading_of(figure.series[0])
                                              : std::to_string(figure.series.size()) + " parameters");
  } else {
    for (const Series& s : figure.series) draw_panel({&s}, heading_of(s));
  }
  if (l.panels > 0)
    canvas.text(kLeft + (kWidth - kLeft - kRight) / 2, l.time_title_y, "time (s)",
                TextStyle{11, false, Anchor::middle, "#000000", false});
  if (l.legend_rows > 0) {
    const auto per_row = static_cast<std::size_t>((kWidth - kLeft - kRight) / kLegendEntry);
    for (std::size_t k = 0; k < figure.series.size(); ++k) {
      const double x = kLeft + static_cast<double>(k % per_row) * kLegendEntry;
      const double y = l.legend_y + static_cast<double>(k / per_row) * kLine;
      const std::string_view colour = kColours[k % std::size(kColours)];
      canvas.line(x, y - 4, x + 22, y - 4, colour, 2);
      canvas.text(x + 28, y, figure.series[k].name, TextStyle{11, false, Anchor::start, "#000000", false});
    }
  }
  for (std::size_t k = 0; k < l.note_lines.size(); ++k)
    canvas.text(kLeft, l.note_y + static_cast<double>(k) * kLine, l.note_lines[k],
                TextStyle{11, false, Anchor::start, kNote, false});
}

}  // namespace fapc::pipeline::plot

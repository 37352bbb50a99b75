// The curves JSON (docs/cli.md, its "Curves JSON" item) against a second writer here, printf's
// "%.10g" over curves_from_frames: frames' curves, which the writer prints without ever building
// them, and a script's curves print what that writer prints. And the thinning of plot lines to
// pixel columns against a second thinning written here: plots thin a line as the figure is built
// and again as it is drawn, which only works if thinning keeps what it already kept.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "fapc/pipeline/convert.hpp"
#include "fapc/transcoder/curves.hpp"
#include "plot/column_picks.hpp"

namespace fapc {
namespace {

std::string printf_number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

// The curves JSON as docs/cli.md describes it, written the slow and obvious way.
std::string reference_json(const Curves& curves) {
  std::string out = "{\n \"fps\": " + std::to_string(curves.fps) +
                    ",\n \"duration\": " + printf_number(curves.duration) + ",\n \"curves\": {";
  const char* separator = "\n";
  for (const auto& [name, points] : curves.curves) {
    out += separator + std::string("  \"") + name + "\": [";
    for (std::size_t i = 0; i < points.size(); ++i)
      out += (i ? ", [" : "[") + printf_number(points[i].first) + ", " + printf_number(points[i].second) + "]";
    out += "]";
    separator = ",\n";
  }
  return out + "\n }\n}\n";
}

std::string json_of(const pipeline::Loaded& loaded) {
  auto bytes = pipeline::render_output(loaded, {"curves.json", ""}, {});
  EXPECT_TRUE(bytes) << bytes.error().message;
  return bytes ? *bytes : "";
}

// Frames with gaps in their numbers at 30 fps (times that are not short decimals), FAP 1 and 2
// now and then, FAPs masked in some frames only, values at the ends of their range.
FapSequence uneven_frames() {
  FapSequence sequence{"uneven", 30, {}};
  std::mt19937 random(19);
  std::int64_t number = 0;
  for (int k = 0; k < 2000; ++k) {
    number += 1 + static_cast<std::int64_t>(random() % 3);
    FapFrame frame;
    frame.number = number;
    if (k % 7 == 0) {
      frame.mask.set(0);
      frame.viseme.select1 = static_cast<int>(random() % 15);
    }
    if (k % 11 == 0) {
      frame.mask.set(1);
      frame.expression.select1 = static_cast<int>(random() % 7);
    }
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (random() % 4 != 0) frame.set(fap, static_cast<std::int32_t>(random() % 2001) - 1000);
    if (k == 5) frame.set(3, INT32_MIN);
    if (k == 6) frame.set(3, INT32_MAX);
    sequence.frames.push_back(frame);
  }
  return sequence;
}

TEST(CurvesJson, FramesPrintAsTheirCurvesWouldWithPrintf) {
  pipeline::Loaded loaded;
  loaded.frames = uneven_frames();
  EXPECT_EQ(json_of(loaded), reference_json(curves_from_frames(loaded.frames)));
}

TEST(CurvesJson, NoFramesNoCurves) {
  pipeline::Loaded loaded;
  loaded.frames.fps = 25;
  const std::string json = json_of(loaded);
  EXPECT_EQ(json, reference_json(curves_from_frames(loaded.frames)));
  EXPECT_EQ(json, "{\n \"fps\": 25,\n \"duration\": 0,\n \"curves\": {\n }\n}\n");
}

// Every kind of number a script's curves hold: integers on both sides of 10^10 (where "%.10g"
// turns to an exponent), -0, fractions short and long, tiny and huge magnitudes.
TEST(CurvesJson, ScriptNumbersPrintAsPrintfTenDigits) {
  Curves curves;
  curves.fps = 25;
  curves.duration = 1234.5678901234;
  auto& edges = curves.curves["edges"];
  for (const double v : {0.0,
                         -0.0,
                         1.0,
                         -1.0,
                         100000.0,
                         9999999999.0,
                         10000000000.0,
                         12345678901.0,
                         -9999999999.0,
                         0.1,
                         1.0 / 3,
                         2.0 / 3,
                         1e-4,
                         1e-5,
                         1.5e-5,
                         123456.789012345,
                         0.000123456789012,
                         1e300,
                         -2.5e-300,
                         4.9e-324,
                         1e16,
                         99999.999995,
                         0.99999999995})
    edges.emplace_back(v, -v);
  std::mt19937_64 random(1919);
  auto& spread = curves.curves["spread"];
  for (int k = 0; k < 20000; ++k) {
    const double mantissa = std::uniform_real_distribution<double>(-10, 10)(random);
    const int exponent = static_cast<int>(random() % 41) - 20;
    const double v = mantissa * std::pow(10.0, exponent);
    spread.emplace_back(static_cast<double>(k) / 30, k % 3 == 0 ? std::round(v) : v);
  }
  pipeline::Loaded loaded;
  loaded.curves = curves;
  EXPECT_EQ(json_of(loaded), reference_json(curves));
}

// Per pixel column: the first, the first lowest, the first highest and the last point, in order.
pipeline::plot::Points reference_picks(const pipeline::plot::Points& points, double duration) {
  pipeline::plot::Points out;
  std::size_t begin = 0;
  while (begin < points.size()) {
    const double column = std::floor(pipeline::plot::time_to_x(points[begin].first, duration));
    std::size_t end = begin;
    while (end < points.size() && std::floor(pipeline::plot::time_to_x(points[end].first, duration)) == column) ++end;
    std::size_t low = begin, high = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (points[i].second < points[low].second) low = i;
      if (points[i].second > points[high].second) high = i;
    }
    std::vector<std::size_t> kept{begin, low, high, end - 1};
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    for (const std::size_t i : kept) out.push_back(points[i]);
    begin = end;
  }
  return out;
}

pipeline::plot::Points picks_of(const pipeline::plot::Points& points, double duration) {
  pipeline::plot::ColumnPicks picks(duration);
  for (const auto& [t, v] : points) picks.add(t, v);
  return picks.take();
}

TEST(PlotThinning, KeepsPerColumnFirstLowestHighestLastAndKeepsItsOwnPicks) {
  std::mt19937 random(7);
  for (const std::size_t count : {1u, 2u, 5u, 1000u, 60000u}) {
    const double duration = static_cast<double>(count) / 25;
    pipeline::plot::Points points;
    for (std::size_t k = 0; k < count; ++k)  // few distinct values: ties between extremes
      points.emplace_back(static_cast<double>(k) / 25, static_cast<double>(random() % 5));
    const pipeline::plot::Points picks = picks_of(points, duration);
    EXPECT_EQ(picks, reference_picks(points, duration)) << count;
    EXPECT_EQ(picks_of(picks, duration), picks) << count;
  }
}

TEST(PlotThinning, AFigureWithoutDurationKeepsEveryPoint) {
  const pipeline::plot::Points points{{0, 1}, {0, 2}, {0, 2}, {0, 0}};
  EXPECT_EQ(picks_of(points, 0), points);
}

}  // namespace
}  // namespace fapc

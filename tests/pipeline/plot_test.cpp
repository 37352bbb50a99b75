// fapc::pipeline::plot_loaded (docs/cli.md, "Plot"): thinning to the panel's pixel columns and its
// cost, parameters left out and said so, points for a single frame, selection by group, the CSV
// table and the cairo formats.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "fapc/pipeline/plot.hpp"

namespace fapc {
namespace {

using pipeline::PlotKind;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// `frames` frames at 25 fps: open_jaw a sine, head_pitch a ramp, bend_nose 0 throughout.
pipeline::Loaded animation(std::size_t frames) {
  pipeline::Loaded loaded;
  loaded.frames.fps = 25;
  for (std::size_t k = 0; k < frames; ++k) {
    FapFrame frame;
    frame.number = static_cast<std::int64_t>(k);
    frame.set(3, static_cast<std::int32_t>(std::lround(500 * std::sin(static_cast<double>(k) / 7))));
    frame.set(48, static_cast<std::int32_t>(k % 1000));
    frame.set(64, 0);
    loaded.frames.frames.push_back(frame);
  }
  return loaded;
}

TEST(Plot, ALongAnimationIsThinnedToWhatItsPanelsShow) {
  const pipeline::Loaded loaded = animation(100000);
  const auto start = std::chrono::steady_clock::now();
  const auto plot = pipeline::plot_loaded(loaded, "long.fap", PlotKind::svg, {});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(plot) << plot.error().message;
  EXPECT_EQ(count(plot->bytes, "<polyline"), 2u);  // open_jaw and head_pitch; bend_nose left out
  // At most four points per pixel column of the 852-pixel plotting width, per line.
  const std::size_t points = count(plot->bytes, ",") - count(plot->bytes, "Not drawn");
  EXPECT_LE(points, 2u * 4 * 853) << points;
  EXPECT_GE(points, 2u * 852) << points;  // and every column still has its points
  EXPECT_LT(plot->bytes.size(), 200000u);
#ifndef FAPC_SANITIZED_BUILD  // set by tests/CMakeLists.txt: clang does not define __SANITIZE_ADDRESS__
  EXPECT_LT(seconds, 0.5) << "issue 19: the SVG plot of 10^5 frames in well under a second";
#endif
  RecordProperty("svg_seconds", std::to_string(seconds));
}

TEST(Plot, ZeroParametersAreLeftOutAndSaidSo) {
  const auto plot = pipeline::plot_loaded(animation(50), "a.fap", PlotKind::svg, {});
  ASSERT_TRUE(plot);
  ASSERT_EQ(plot->notes.size(), 1u);
  EXPECT_EQ(plot->notes[0], "1 parameter not drawn, zero throughout: bend_nose");
  EXPECT_NE(plot->bytes.find("Not drawn, zero throughout: bend_nose"), std::string::npos);
  // Panels in FAP order, titled with their FAP numbers and units.
  const auto jaw = plot->bytes.find("open_jaw (FAP 3)");
  const auto head = plot->bytes.find("head_pitch (FAP 48)");
  EXPECT_LT(jaw, head);
  EXPECT_NE(plot->bytes.find("value (MNS)"), std::string::npos);
  EXPECT_NE(plot->bytes.find("value (AU)"), std::string::npos);
  EXPECT_NE(plot->bytes.find("time (s)"), std::string::npos);
}

TEST(Plot, ASingleFrameIsDrawnAsPoints) {
  pipeline::Loaded one = animation(1);
  one.frames.frames[0].set(3, 120);
  one.frames.frames[0].set(48, -40);
  const auto plot = pipeline::plot_loaded(one, "one.fap", PlotKind::svg, {});
  ASSERT_TRUE(plot);
  EXPECT_EQ(count(plot->bytes, "<polyline"), 0u);
  EXPECT_EQ(count(plot->bytes, "<circle"), 2u);
}

TEST(Plot, GroupsSelectAndOverlayAddsALegend) {
  pipeline::PlotOptions options;
  options.faps = "head";
  options.overlay = true;
  const auto plot = pipeline::plot_loaded(animation(50), "a.fap", PlotKind::svg, options);
  ASSERT_TRUE(plot);
  EXPECT_EQ(count(plot->bytes, "<polyline"), 1u);
  EXPECT_EQ(plot->bytes.find("open_jaw"), std::string::npos);
  options.faps = "hed";
  const auto misspelt = pipeline::plot_loaded(animation(50), "a.fap", PlotKind::svg, options);
  ASSERT_FALSE(misspelt);
  EXPECT_EQ(misspelt.error().kind, ErrorKind::usage);
  EXPECT_NE(misspelt.error().message.find("did you mean head?"), std::string::npos);
  options.faps = "tongue";
  const auto none = pipeline::plot_loaded(animation(50), "a.fap", PlotKind::svg, options);
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().kind, ErrorKind::usage);
}

TEST(Plot, CsvHasOneRowPerFrameAndOneColumnPerFap) {
  pipeline::PlotOptions options;
  options.faps = "3,nose";
  const auto csv = pipeline::plot_loaded(animation(3), "a.fap", PlotKind::csv, options);
  ASSERT_TRUE(csv);
  // sin(1/7) * 500 = 71.2..., sin(2/7) * 500 = 140.9...
  EXPECT_EQ(csv->bytes, "frame,time_s,open_jaw,bend_nose\n0,0,0,0\n1,0.04,71,0\n2,0.08,141,0\n");
}

TEST(Plot, PngAndPdfComeFromCairo) {
  const auto png = pipeline::plot_loaded(animation(50), "a.fap", PlotKind::png, {});
  ASSERT_TRUE(png);
  EXPECT_EQ(png->bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const auto pdf = pipeline::plot_loaded(animation(50), "a.fap", PlotKind::pdf, {});
  ASSERT_TRUE(pdf);
  EXPECT_EQ(pdf->bytes.substr(0, 5), "%PDF-");
}

}  // namespace
}  // namespace fapc

// What each output reads (OutputFormat::uses_frames, ::uses_curves) decides what convert() keeps of
// a script: its frames only when an output reads them, its curves likewise. Two checks, each able
// to fail on its own:
//  - every writer's flags are honest: what a writer is said not to read can be taken away (or
//    replaced by other data) without changing one byte it writes;
//  - a script compiled to outputs that read no frames gives the bytes, warnings, errors and summary
//    of the whole load (frames, curves and all), over the corpus's scripts, good and bad.
#include <gtest/gtest.h>

#include <filesystem>

#include "fapc/pipeline/convert.hpp"
#include "pipeline_test_helpers.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;
using pipeline::ConvertOptions;
using pipeline::Loaded;

// The text a writer gives: its bytes, or its error as printed.
std::string written(const Loaded& loaded, const pipeline::OutputFormat& format, const std::string& path) {
  auto bytes = format.write(loaded, path, ConvertOptions{});
  return bytes ? *bytes : "error: " + format_diagnostic(bytes.error());
}

// Frames unlike the script's: if a writer said not to read the frames did read them, its bytes
// would change.
FapSequence other_frames(const FapSequence& frames) {
  FapSequence other{frames.name, frames.fps, {}};
  for (int k = 0; k < 7; ++k) {
    FapFrame frame;
    frame.number = k;
    frame.set(3, 100 * k);
    frame.set(48, -40 * k);
    other.frames.push_back(frame);
  }
  return other;
}

// A script with a timeline, frames, curves and a voice: every writer has what it could read.
Loaded whole_script() {
  auto loaded = pipeline::load(test::corpus_dir() + "/fml/figure6.fml", ConvertOptions{});
  EXPECT_TRUE(loaded) << format_diagnostic(loaded.error());
  EXPECT_TRUE(loaded->timeline && loaded->curves && !loaded->frames.frames.empty());
  return std::move(*loaded);
}

TEST(OutputNeeds, WritersReadNothingTheirFlagsDeny) {
  const test::TempFolder tmp;
  const Loaded whole = whole_script();
  std::size_t without_frames = 0, without_curves = 0;
  for (const pipeline::OutputFormat& format : pipeline::formats().outputs()) {
    // The face videos read the frames and nothing else the script has; they are slow to make.
    if (format.kind == "webm" || format.kind == "html") continue;
    const std::string path = tmp / ("x" + format.extensions.front());
    SCOPED_TRACE(format.kind);
    const std::string expected = written(whole, format, path);
    if (!format.uses_frames) {
      ++without_frames;
      Loaded no_frames = whole;
      no_frames.frames.frames.clear();
      EXPECT_EQ(written(no_frames, format, path), expected);
      Loaded wrong_frames = whole;
      wrong_frames.frames = other_frames(whole.frames);
      EXPECT_EQ(written(wrong_frames, format, path), expected);
    }
    if (!format.uses_curves) {
      ++without_curves;
      Loaded no_curves = whole;
      no_curves.curves.reset();
      EXPECT_EQ(written(no_curves, format, path), expected);
    }
  }
  EXPECT_GE(without_frames, 5u);  // json, svg, pdf, timeline, wav
  EXPECT_GE(without_curves, 8u);
}

// And the reverse: a writer that reads the frames (a .csv) or the curves (a .json) writes other
// bytes from other frames or without curves, so the check above can tell a flag's lie.
TEST(OutputNeeds, WritersThatReadDataChangeWithIt) {
  const test::TempFolder tmp;
  const Loaded whole = whole_script();
  const pipeline::OutputFormat* csv = pipeline::formats().output_named("csv");
  const pipeline::OutputFormat* json = pipeline::formats().output_named("json");
  ASSERT_TRUE(csv && json);
  EXPECT_TRUE(csv->uses_frames);
  EXPECT_FALSE(csv->uses_curves);
  EXPECT_FALSE(json->uses_frames);
  EXPECT_TRUE(json->uses_curves);
  Loaded wrong_frames = whole;
  wrong_frames.frames = other_frames(whole.frames);
  EXPECT_NE(written(wrong_frames, *csv, tmp / "x.csv"), written(whole, *csv, tmp / "x.csv"));
  Loaded no_curves = whole;
  no_curves.curves.reset();
  EXPECT_NE(written(no_curves, *json, tmp / "x.json"), written(whole, *json, tmp / "x.json"));
}

// What the whole load's frames were.
pipeline::FramesSeen seen_in(const FapSequence& sequence) {
  Loaded loaded;
  loaded.frames = sequence;
  return pipeline::frames_seen(loaded);
}

TEST(OutputNeeds, CurveOutputsOfScriptsMatchTheWholeLoad) {
  const test::TempFolder tmp;
  std::vector<ConvertOptions> settings(4);
  for (ConvertOptions& options : settings) options.speech_engine = false;  // the same visemes twice
  settings[1].fps = 10;
  settings[2].limits.max_frames = 40;  // most corpus scripts are longer: the render's error
  settings[3].strict = true;
  std::size_t scripts = 0, failing = 0, warned = 0;
  for (const std::string& input : test::corpus_scripts()) {
    ++scripts;
    for (const ConvertOptions& options : settings) {
      const std::vector<pipeline::OutputRequest> outputs = {
          {tmp / "x.json", ""}, {tmp / "x.svg", ""}, {tmp / "x.timeline", ""}};
      ConvertOptions everything = options;  // frames and curves, as before outputs said what they read
      everything.frames = true;
      everything.curves = true;
      const test::LoadedWay expected = test::load_then_write(input, outputs, everything);
      auto whole = pipeline::load(input, everything);
      for (const auto& request : outputs) fs::remove(request.path);
      const pipeline::ConvertResult result = pipeline::convert(input, outputs, options);
      SCOPED_TRACE(input + " at " + std::to_string(options.fps) + " fps");
      EXPECT_TRUE(result.loaded.frames.frames.empty());  // rendered, not held
      failing += expected.error.has_value();
      warned += !expected.warnings.empty();
      test::expect_as_loaded(result, expected, outputs);
      if (!expected.error && whole) {
        const pipeline::FramesSeen seen = seen_in(whole->frames);
        EXPECT_EQ(result.frames.count, seen.count);
        EXPECT_EQ(result.frames.fps, seen.fps);
        EXPECT_EQ(result.frames.faps, seen.faps);
        EXPECT_EQ(result.frames.duration_seconds(), whole->frames.duration_seconds());
      }
    }
  }
  EXPECT_GT(scripts, 40u);
  EXPECT_GT(failing, 10u);
  EXPECT_GT(warned, 0u);
}

}  // namespace
}  // namespace fapc

// A script too long for the frame limit is refused by its front end as soon as it is scheduled,
// before its clips are made (FrameBudget, docs/security.md "Resource limits"), with the error that
// rendering its timeline would give. The second way: the front end without the budget, then
// FrameStream::start on its timeline, which is where the limit was checked before.
#include <gtest/gtest.h>

#include <fstream>

#include "fapc/pipeline/registry.hpp"
#include "pipeline_test_helpers.hpp"
#include "support/test_support.hpp"
#include "timeline_input.hpp"

namespace fapc {
namespace {

using pipeline::ConvertOptions;

// The front end with the budget and without, against one setting. Returns whether the limit
// refused the script.
bool expect_refused_as_rendering_would(const std::string& input, const ConvertOptions& options) {
  SCOPED_TRACE(input + " at " + std::to_string(options.fps) + " fps, at most " +
               std::to_string(options.limits.max_frames) + " frames");
  ConvertOptions unchecked = options;  // no frames made, none counted
  unchecked.render = false;
  ConvertOptions checked = unchecked;  // no frames made either, but the budget given
  checked.renders_later = true;
  const Result<pipeline::Loaded> early = pipeline::load(input, checked);
  const Result<pipeline::Loaded> lowered = pipeline::load(input, unchecked);
  if (!lowered) {  // the front end's own error comes first either way
    EXPECT_FALSE(early);
    if (!early) {
      EXPECT_EQ(format_diagnostic(early.error()), format_diagnostic(lowered.error()));
    }
    return false;
  }
  const Result<Profile> profile = pipeline::profile_for(options);
  EXPECT_TRUE(profile);
  const Result<FrameStream> stream = pipeline::stream_frames(*lowered->timeline, input, *profile, options);
  if (stream || stream.error().kind != ErrorKind::limit_exceeded) {
    EXPECT_TRUE(early) << format_diagnostic(early.error());
    return false;
  }
  EXPECT_FALSE(early);
  if (early) return false;
  EXPECT_EQ(format_diagnostic(early.error()), format_diagnostic(stream.error()));
  EXPECT_EQ(early.error().kind, ErrorKind::limit_exceeded);
  return true;
}

ConvertOptions limited(int fps, std::int64_t max_frames) {
  ConvertOptions options;
  options.speech_engine = false;  // the letter table: the same visemes every time
  options.fps = fps;
  options.limits.max_frames = max_frames;
  return options;
}

TEST(EarlyFrameLimit, RefusesEveryCorpusScriptAsRenderingItsTimelineWould) {
  std::size_t refused = 0, scripts = 0;
  for (const std::string& input : test::corpus_scripts()) {
    ++scripts;
    for (const ConvertOptions& options : {limited(25, 1), limited(25, 40), limited(25, 300), limited(100, 1000)})
      refused += expect_refused_as_rendering_would(input, options);
  }
  EXPECT_GT(scripts, 40u / test::kSweepStride);
  EXPECT_GT(refused,
            40u / test::kSweepStride);  // most scripts at the lowest limits: errors compared, not only successes
}

// The Mimic compiler works out the timeline's end and the clip that ends it before making any
// clip: what it must agree with is the lowering's own choices (a list starts at its first time, a
// run cut to nothing makes no clip, of two runs ending last the later is named).
TEST(EarlyFrameLimit, MimicFindsTheEndAndTheClipThatEndsItAsTheTimelineDoes) {
  const test::TempFolder tmp;
  const std::vector<std::string> programs = {
      "main {\njaw <in=1,hold=1,out=1,value=0.5>;\nlookat_x ( 3 9; 0 100; )\n}\n",
      "main {\n[\njaw <in=1,hold=1,out=1,value=0.5>;\nhead_rot_y <in=1,hold=1,out=1,value=5>;\n]\n}\n",
      "main {\n[\njaw <in=2,hold=2,out=2,value=0.5>;\nhead_rot_y <left=-1,in=1,hold=1,out=1,value=5>;\n]\n}\n",
      "main {\njaw <in=1,hold=1,out=1,value=0.5>;\nlookat_x ( 2; 7; )\n}\n",
      "main {\n[\njaw <min=0,max=0.09,freq=0.1,sin,duration=7>;\nlookat_x ( 0 4 5; 0 100 0; )\n]\n}\n",
  };
  std::size_t refused = 0;
  for (std::size_t p = 0; p < programs.size(); ++p) {
    const std::string path = tmp / ("program" + std::to_string(p) + ".mimic");
    std::ofstream(path) << programs[p];
    // Every limit from far below the length to past it.
    for (std::int64_t max_frames = 1; max_frames <= 260; max_frames += 7)
      refused += expect_refused_as_rendering_would(path, limited(25, max_frames));
  }
  EXPECT_GT(refused, 50u);
}

}  // namespace
}  // namespace fapc

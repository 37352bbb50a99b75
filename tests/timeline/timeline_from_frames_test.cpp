// Frames -> clips -> frames gives the frames back (the property timeline_from_frames promises).
#include <gtest/gtest.h>

#include <algorithm>

#include "fapc/codec/fap_file.hpp"
#include "fapc/timeline/timeline_from_frames.hpp"
#include "fapc/transcoder/render.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

TEST(TimelineFromFrames, RenderingAtTheSameRateGivesTheFramesBack) {
  int checked = 0;
  for (const std::string name :
       {"fap/copperdong__Xface/joy.fap", "fap/copperdong__Xface/anger.fap", "examples/fap/greta-lips.fap"}) {
    const std::string path = test::corpus_dir() + "/" + name;
    auto read = read_fap_text(test::read_text(path), path);
    ASSERT_TRUE(read.ok()) << name;
    const FapSequence& in = read->sequence;
    const Timeline timeline = timeline_from_frames(in, 0, Location::text(name, 0, 0));
    RenderOptions options;
    options.fps = in.fps;
    const auto out = render_frames(timeline, options);
    ASSERT_TRUE(out.ok()) << name;
    ASSERT_EQ(out->frames.frames.size(), in.frames.size()) << name;
    for (std::size_t k = 0; k < in.frames.size(); ++k) {
      const FapFrame& a = in.frames[k];
      const FapFrame& b = out->frames.frames[k];
      for (int fap = 3; fap <= kFapCount; ++fap) {
        ASSERT_EQ(a.has(fap), b.has(fap)) << name << " frame " << k << " fap " << fap;
        if (!a.has(fap)) continue;
        const int limit = find_fap(fap)->legal_max();  // rendering clamps; the input may not
        ASSERT_EQ(std::clamp(a.value(fap), -limit, limit), b.value(fap)) << name << " frame " << k << " fap " << fap;
      }
      if (a.has(2)) {
        ASSERT_EQ(a.expression.select1, b.expression.select1);
        ASSERT_EQ(a.expression.intensity1, b.expression.intensity1);
      }
    }
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(TimelineFromFrames, GapsSplitClipsAndShiftMovesThem) {
  FapSequence s;
  s.fps = 10;
  for (const std::int64_t n : {0, 1, 2, 5}) {
    FapFrame f;
    f.number = n;
    f.set(3, static_cast<std::int32_t>(10 * n));
    s.frames.push_back(f);
  }
  const Timeline t = timeline_from_frames(s, 2, Location{});
  ASSERT_EQ(t.clips.size(), 2u);
  EXPECT_DOUBLE_EQ(t.clips[0].begin, 2.0);
  EXPECT_DOUBLE_EQ(t.clips[0].end, 2.3);
  EXPECT_EQ(t.clips[0].curve.keys.size(), 2u);  // 0, 10, 20 lie on one line
  EXPECT_DOUBLE_EQ(t.clips[1].begin, 2.5);
  EXPECT_DOUBLE_EQ(t.end(), 2.6);
}

}  // namespace
}  // namespace fapc

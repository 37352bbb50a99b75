// The check of the speech sync tests of BML and SMIL-Agent: a script's behaviour synced to a
// speech mark moves FAP `fap` first within one frame of the onset of voiced stretch `stretch` of
// its audio (support/voiced_segments.hpp), the marked word after a pause.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/engine.hpp"
#include "support/voiced_segments.hpp"

namespace fapc::test {

inline void expect_moves_with_word(const std::string& script, int fap, std::size_t stretch) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  constexpr int kFps = 25;
  pipeline::ConvertOptions options;
  options.fps = kFps;
  Result<pipeline::Loaded> loaded = pipeline::load(script, options);
  ASSERT_TRUE(loaded) << format_diagnostic(loaded.error());
  ASSERT_TRUE(loaded->audio);
  const std::vector<double> onsets = voiced_onsets(*loaded->audio, 0.1);
  ASSERT_GT(onsets.size(), stretch) << "the marked word should follow a pause";
  const double moved = first_move(loaded->frames, fap);
  std::printf("word onset %.3f s, behaviour starts %.3f s\n", onsets[stretch], moved);
  EXPECT_NEAR(moved, onsets[stretch], 1.0 / kFps + 0.01);
}

}  // namespace fapc::test

// Shared by the face tests: golden images compared within a tolerance, sequences made by hand.
#pragma once

#include <string>

#include "fapc/codec/fap_sequence.hpp"
#include "fapc/face/image.hpp"

namespace fapc::test {

// The pixel tolerance of every golden image (docs/render.md): a pixel differs when one of its
// channels differs by more than kChannelTolerance; at most kPixelShare of the pixels may differ,
// and the mean channel difference stays below kMeanTolerance. Room for anti-aliasing that
// another cairo or pixman version may round differently, not for a moved feature.
inline constexpr int kChannelTolerance = 24;
inline constexpr double kPixelShare = 0.0005;
inline constexpr double kMeanTolerance = 0.5;

// Compares `actual` with corpus/`path` within the tolerance, or rewrites it under
// FAPC_REGENERATE_GOLDEN=1.
void expect_golden_image(const std::string& path, const face::Image& actual);

// A sequence of `frames` frames at `fps` in which FAP `fap` holds `value` (all other FAPs 0).
FapSequence constant_sequence(int fap, int value, int frames = 1, int fps = 25);

}  // namespace fapc::test

// OpenFace's FeatureExtraction CSV (2.0 and 1.x, and the column subsets other tools keep) to
// FAPs: action unit intensities through fapc's AU table, head pose to FAPs 48-50, gaze to 23-26
// (docs/bridges.md, "Inputs: OpenFace and ARKit CSVs").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "track_read.hpp"

namespace fapc::pipeline::bridges {

// Below this `confidence`, or with `success` 0, a row is not trusted: it holds the last trusted
// face (docs/bridges.md).
inline constexpr double kMinConfidence = 0.5;
// OpenFace's AUxx_r scale, 0..5 (FACS A..E): 5 is a table row's full amount.
inline constexpr double kFullIntensity = 5;

// True when the header names columns only OpenFace writes (AUxx_r, AUxx_c, pose_R*, gaze_angle_*,
// gaze_0_*).
bool looks_like_openface(const std::vector<std::string>& header);

Result<TrackRead> read_openface_csv(std::string_view text, const std::string& file, const TrackOptions& options);

}  // namespace fapc::pipeline::bridges

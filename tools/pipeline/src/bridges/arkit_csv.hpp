// ARKit blendshape CSVs to FAPs through fapc's ARKit table: the Live Link Face app's takes
// (Timecode, BlendShapeCount, the 52 shapes in PascalCase, head and eye angles) and the same 52
// names in camelCase as MediaPipe's face landmarker gives them, `_neutral` included
// (docs/bridges.md, "Inputs: OpenFace and ARKit CSVs").
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "track_read.hpp"

namespace fapc::pipeline::bridges {

// Live Link Face's angle columns (radians), in its order after the shapes, and the FAP each
// drives with its sign; the eye rolls drive none (FAPs have no eyeball roll).
struct ArkitAngle {
  std::string_view name;
  int fap;  // 0: no FAP carries it
  double sign;
};
const std::array<ArkitAngle, 9>& arkit_angle_columns();

// True when the header has a Timecode column or names an ARKit shape.
bool looks_like_arkit(const std::vector<std::string>& header);

Result<TrackRead> read_arkit_csv(std::string_view text, const std::string& file, const TrackOptions& options);

// "13:13:04:31.652" at a timecode rate: seconds; nullopt if it is not HH:MM:SS:FF[.fff].
std::optional<double> timecode_seconds(std::string_view text, int rate);
// The frame field (FF) of a timecode, or -1.
int timecode_frame_field(std::string_view text);

}  // namespace fapc::pipeline::bridges

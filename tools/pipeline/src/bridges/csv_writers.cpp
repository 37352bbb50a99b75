// ARKit CSV in Live Link Face's layout and action units in OpenFace 2.0's, from the frames as the
// face shows them.
#include <cmath>
#include <cstdio>

#include "arkit_csv.hpp"
#include "bases.hpp"
#include "fapc/face/face_track.hpp"
#include "fapc/vocabulary/arkit_shapes.hpp"
#include "openface_csv.hpp"
#include "writers.hpp"

namespace fapc::pipeline::bridges {
namespace {

void append_fixed(std::string& out, double value, int decimals) {
  char text[48];
  const int n = std::snprintf(text, sizeof text, "%.*f", decimals, value == 0 ? 0.0 : value);  // no "-0"
  out.append(text, static_cast<std::size_t>(std::max(n, 0)));
}

// HH:MM:SS:FF.000 at the frames' own rate (Live Link Face stamps its takes so; the reader takes
// the rate from the largest FF).
std::string timecode(std::int64_t frame, int fps) {
  const std::int64_t seconds = frame / fps;
  char text[40];
  std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld:%02lld.000", static_cast<long long>(seconds / 3600 % 100),
                static_cast<long long>(seconds / 60 % 60), static_cast<long long>(seconds % 60),
                static_cast<long long>(frame % fps));
  return text;
}

// Calls row(k, values, weights) for every frame k of the face track: the values the face shows
// and the basis's weights fitted to them, each frame on its own.
template <class Row>
void for_each_fitted_frame(const FapSequence& frames, const vocabulary::ShapeBasis& basis, Row row) {
  const face::FaceTrack track(frames);
  for (std::int64_t k = 0; k < track.frame_count(); ++k) {
    const face::FapValues& values = track.at_frame(k);
    row(k, values, basis.from_faps(values));
  }
}

}  // namespace

std::string write_arkit_csv(const FapSequence& frames) {
  std::string out = "Timecode,BlendShapeCount";
  for (std::string_view name : vocabulary::arkit_shape_names()) out += "," + vocabulary::pascal_case(name);
  for (const ArkitAngle& angle : arkit_angle_columns()) out += "," + std::string(angle.name);
  out += '\n';
  const int fps = frames.fps > 0 ? frames.fps : 25;
  for_each_fitted_frame(
      frames, arkit_basis(), [&](std::int64_t k, const face::FapValues& values, const std::vector<double>& weights) {
        out += timecode(k, fps);
        out += "," + std::to_string(vocabulary::kArkitShapeCount + arkit_angle_columns().size());
        for (double w : weights) out += ',', append_fixed(out, w, 6);
        for (const ArkitAngle& angle : arkit_angle_columns()) {
          out += ',';
          append_fixed(
              out, angle.fap ? values[static_cast<std::size_t>(angle.fap - 1)] / (angle.sign * kRadiansToAu) : 0.0, 6);
        }
        out += '\n';
      });
  return out;
}

std::string write_openface_csv(const FapSequence& frames) {
  // OpenFace 2.0's columns in its order, the subset fapc can fill, with its ", " separator.
  std::string out =
      "frame, face_id, timestamp, confidence, success, gaze_angle_x, gaze_angle_y, pose_Rx, pose_Ry, pose_Rz";
  for (int au : openface_intensity_units()) {
    char name[16];
    std::snprintf(name, sizeof name, ", AU%02d_r", au);
    out += name;
  }
  out += '\n';
  const int fps = frames.fps > 0 ? frames.fps : 25;
  for_each_fitted_frame(frames, openface_basis(),
                        [&](std::int64_t k, const face::FapValues& v, const std::vector<double>& weights) {
                          out += std::to_string(k + 1) + ", 0, ";  // OpenFace numbers frames from 1
                          append_fixed(out, static_cast<double>(k) / fps, 3);
                          out += ", 1, 1";  // fapc's frames are the face itself: full confidence, tracked
                          // Both eyes' mean direction, and the head (the reader's axes, docs/bridges.md).
                          for (double value : {(v[22] + v[23]) / 2, (v[24] + v[25]) / 2, v[47], v[48], v[49]}) {
                            out += ", ";
                            append_fixed(out, value / kRadiansToAu, 3);
                          }
                          for (double w : weights) {
                            out += ", ";
                            append_fixed(out, w * kFullIntensity, 2);
                          }
                          out += '\n';
                        });
  return out;
}

}  // namespace fapc::pipeline::bridges

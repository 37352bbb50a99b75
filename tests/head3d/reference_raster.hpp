// A second, independent drawing of the 3D head for the browser test: fapc::head3d's mesh for one
// frame (neutral + sum of weight x target, the head's and eyes' rotations), projected with a
// perspective camera given as three.js's PerspectiveCamera takes it, back faces culled, hidden
// surfaces removed with a depth buffer. It draws which material covers each pixel, not colours:
// the test compares shapes (silhouette, what changes between frames), which do not depend on the
// shading model.
#pragma once

#include <array>
#include <vector>

#include "fapc/head3d/head_morphs.hpp"

namespace fapc::head3d::reference {

struct Camera {
  double fov_degrees = 24;  // vertical
  double aspect = 4.0 / 3;
  std::array<double, 3> position{};  // metres, glTF scene coordinates
  std::array<double, 3> target{};
};

// One entry per pixel, rows top to bottom: the Material drawn there, or -1 for the background.
struct MaterialImage {
  int width = 0;
  int height = 0;
  std::vector<int> material;
  // How far (millimetres) the surface drawn at each pixel lies from where it is in the other frame
  // given to rasterise_frame; 0 on the background or without another frame.
  std::vector<double> motion;
  // How much light each pixel's surface takes from a lamp above, left of and in front of the face
  // (0.3 ambient + 0.7 Lambert, from the neutral mesh's smooth normals turned with the head and
  // eyes), and 1 / its depth (larger is nearer; 0 on the background): for the documentation's
  // pictures of the head, which the browser test does not use.
  std::vector<double> shade;
  std::vector<double> inverse_depth;
  int at(int x, int y) const { return material[static_cast<std::size_t>(y) * width + x]; }
};

// Where `point` (metres, scene coordinates) falls in a picture of width x height taken by `camera`:
// x, y in pixels (y down) and 1 / its depth; depth 0 when it is behind the camera.
std::array<double, 3> project_point(const Camera& camera, int width, int height, const std::array<double, 3>& point);

MaterialImage rasterise_frame(const HeadFrame& frame, const Camera& camera, int width, int height,
                              const HeadFrame* other = nullptr);

}  // namespace fapc::head3d::reference

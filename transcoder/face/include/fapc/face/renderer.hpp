// Draws the posed face with cairo: filled contours as smooth curves through the feature points,
// back to front under the head's rotation. One renderer per picture size; it keeps its drawing
// surface between frames, so rendering a sequence allocates once.
#pragma once

#include <memory>

#include "fapc/face/face_track.hpp"
#include "fapc/face/image.hpp"

namespace fapc::face {

// Picture sizes the renderer accepts (each side), checked by callers before rendering.
inline constexpr int kMinSide = 16;
inline constexpr int kMaxSide = 7680;

class FaceRenderer {
 public:
  FaceRenderer(int width, int height);
  ~FaceRenderer();
  FaceRenderer(const FaceRenderer&) = delete;
  FaceRenderer& operator=(const FaceRenderer&) = delete;

  // Marks every feature point on the pictures that follow: the standard's points numbered in
  // red, the drawing's own contour points in grey (docs/render.md's chart).
  void show_feature_points(bool show);

  // Draws the face showing `values` over the whole picture; returns it (valid until the next call).
  const Image& render(const FapValues& values);

  int width() const;
  int height() const;
  // Pixels per millimetre of face, and where the neutral face's point `p` lands (tests measure
  // FAP motions on the image with these).
  double scale() const;
  double screen_x(double face_x) const;
  double screen_y(double face_y) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The radius (mm) about 7.1 that every point of the face stays within under any head rotation;
// the picture's shorter side spans its diameter.
double framing_radius();

}  // namespace fapc::face

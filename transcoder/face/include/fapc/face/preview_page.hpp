// The .html preview: one self-contained page (no network, no sibling files) with the face video
// embedded as a data: URI, the curves of every FAP that moves with a cursor that follows playback,
// play/pause, a scrubber, and the FAP values at the cursor. `#t=SECONDS` in the URL seeks on load.
#pragma once

#include <string>
#include <string_view>

#include "fapc/face/face_track.hpp"

namespace fapc::face {

// What the page shows of the face: the video of the 2D face, the 3D head (three.js playing the
// glTF of the same frames, docs/render.md "The 3D view"), or both side by side.
enum class PreviewView { two_d, three_d, both };

struct PreviewOptions {
  int width = 640;
  int height = 480;
  int frame_rate = 25;  // the video's pictures per second
  std::string title;
  bool sound = false;  // the video carries a voice: the player is not muted
  PreviewView view = PreviewView::two_d;
  std::string head_glb;  // the .glb the 3D view plays (fapc::head3d's head and animation); unused in 2d
};

// Layout facts the browser test relies on: the video sits at the page's top-left corner at its
// own size; the curve plot is kPlotWidth wide and its time axis runs from kPlotMargin to
// kPlotWidth - kPlotMargin.
inline constexpr int kPlotWidth = 640;
inline constexpr int kPlotMargin = 40;
// The 3D view's canvas is as large as the video and sits at the top, at this x: the page's left
// edge in 3d (the video is hidden: it still carries the clock and the voice), right of it in both.
int head3d_left(const PreviewOptions& options);

std::string preview_page(const FaceTrack& track, std::string_view webm, const PreviewOptions& options);

std::string base64(std::string_view bytes);

}  // namespace fapc::face

// The .html preview: one self-contained page (no network, no sibling files) with the face video
// embedded as a data: URI, the curves of every FAP that moves with a cursor that follows playback,
// play/pause, a scrubber, and the FAP values at the cursor. `#t=SECONDS` in the URL seeks on load.
#pragma once

#include <string>
#include <string_view>

#include "fapc/face/face_track.hpp"

namespace fapc::face {

struct PreviewOptions {
  int width = 640;
  int height = 480;
  int frame_rate = 25;  // the video's pictures per second
  std::string title;
  bool sound = false;  // the video carries a voice: the player is not muted
};

// Layout facts the browser test relies on: the video sits at the page's top-left corner at its
// own size; the curve plot is kPlotWidth wide and its time axis runs from kPlotMargin to
// kPlotWidth - kPlotMargin.
inline constexpr int kPlotWidth = 640;
inline constexpr int kPlotMargin = 40;

std::string preview_page(const FaceTrack& track, std::string_view webm, const PreviewOptions& options);

std::string base64(std::string_view bytes);

}  // namespace fapc::face

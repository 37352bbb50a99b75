// The still outputs: one frame, and a contact sheet of frames in a grid with their time stamps.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/face/face_track.hpp"
#include "fapc/face/image.hpp"

namespace fapc::face {

struct PictureOptions {
  int width = 640;
  int height = 480;
  std::optional<std::int64_t> frame;  // --frame K (on the sequence's grid)
  std::optional<double> time;         // --time T seconds
  std::optional<int> sheet;           // --sheet N: N frames in a grid
  int frame_rate = 0;                 // video outputs: pictures per second (0: the input's rate)
  bool points = false;                // --points: mark and number the feature points
  Limits limits;                      // pixels per picture and per sheet (docs/security.md)
  // Video outputs: told of the pictures encoded so far and how many there are; may be empty.
  std::function<void(std::int64_t done, std::int64_t total)> progress;
};

inline constexpr int kMaxSheetFrames = 400;

// Checks sizes and counts (usage errors for what the options cannot mean, limit errors past the
// named limits: pixels of a picture, of a sheet); `where` names the output in errors.
Status check_picture_options(const PictureOptions& options, const std::string& where);

// The frame `--frame`/`--time` picks (frame 0 when neither is given), or a contact sheet when
// `sheet` is set: N times spread evenly from 0 to the last frame, each cell of width x height, in
// a grid about as square as the cells allow, each stamped with its time.
Result<Image> render_picture(const FaceTrack& track, const PictureOptions& options, const std::string& where);

// The .png output of a sequence: the picture render_picture draws, as PNG bytes.
Result<std::string> face_png(const FapSequence& sequence, const PictureOptions& options, const std::string& where);

// The times of a sheet's cells: N instants from 0 to the start of the last frame, evenly spread.
std::vector<double> sheet_times(const FaceTrack& track, int cells);

}  // namespace fapc::face

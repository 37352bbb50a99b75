// The face as a video: VP9 in WebM, written through libavcodec/libavformat into memory.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/face/face_track.hpp"

namespace fapc::face {

// Speech to put beside the picture, as Opus (resampled to 48 kHz); see docs/render.md.
struct AudioInput {
  int sample_rate = 48000;
  int channels = 1;
  std::vector<float> samples;  // interleaved, -1..1
  double start = 0;            // seconds on the face's clock; sound before 0 is cut
};

struct VideoOptions {
  int width = 640;
  int height = 480;
  int frame_rate = 0;  // pictures per second; 0: the sequence's own rate
  Limits limits;       // pixels a picture, pixels in all (docs/security.md)
  // Told of the pictures encoded so far, and how many there are (a progress bar); may be empty.
  std::function<void(std::int64_t done, std::int64_t total)> progress;
};

inline constexpr double kMaxVideoSeconds = 4 * 3600.0;

// The number of pictures a video of `track` has: duration x rate, rounded, at least 1.
std::int64_t video_frame_count(const FaceTrack& track, int frame_rate);
// The same for a sequence of `frames` frames on a grid of `fps`, known before they are made.
std::int64_t video_frame_count(std::int64_t frames, int fps, int frame_rate);

// What encode_webm refuses from the picture size, the rate and the length alone, before any
// picture is drawn: usage errors for sizes and rates the encoder cannot take; limit_exceeded past
// kMaxVideoSeconds, Limits::max_frame_pixels or Limits::max_video_pixels. A pipeline asks it of an
// animation's length before rendering its frames (docs/security.md, "Resource limits"), with the
// place that ends the animation as `length_at` (the length errors) and the output as `at` (the
// others); encode_webm asks it again of the frames it is given.
Status check_video(std::int64_t frames, int fps, const VideoOptions& options, const Location& at,
                   const Location& length_at);

// `where` names the output in errors. Usage errors for odd sizes (4:2:0 video needs even sides)
// and bad rates; limit_exceeded past kMaxVideoSeconds; unsupported when libav lacks libvpx-vp9
// (or libopus, for audio). Without audio the bytes are what they were before audio existed.
Result<std::string> encode_webm(const FaceTrack& track, const VideoOptions& options, const AudioInput* audio,
                                const std::string& where);

}  // namespace fapc::face

#include "fapc/face/pictures.hpp"
#include "fapc/face/preview_page.hpp"

namespace fapc::face {

// The .webm and .html outputs of a sequence (size and frame rate from `options`; the still-picture
// choices --frame/--time/--sheet do not apply). The page embeds the video it encodes.
// `audio`, when given, plays beside the face (and unmutes the page's video).
Result<std::string> face_webm(const FapSequence& sequence, const PictureOptions& options, const AudioInput* audio,
                              const std::string& where);
// `view` and `head_glb` as in PreviewOptions: the 3D view plays that .glb (made by the caller,
// fapc::head3d, from the same sequence).
Result<std::string> face_html(const FapSequence& sequence, const PictureOptions& options, const AudioInput* audio,
                              const std::string& title, const std::string& where, PreviewView view = PreviewView::two_d,
                              std::string head_glb = {});

}  // namespace fapc::face

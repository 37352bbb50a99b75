// The .webm and .html outputs: the face video, and the preview page around it.
#include "fapc/face/preview_page.hpp"
#include "fapc/face/webm.hpp"

#include <utility>

namespace fapc::face {

namespace {

VideoOptions video_options(const PictureOptions& options) {
  return VideoOptions{options.width, options.height, options.frame_rate, options.limits, options.progress};
}

}  // namespace

Result<std::string> face_webm(const FapSequence& sequence, const PictureOptions& options, const AudioInput* audio,
                              const std::string& where) {
  return encode_webm(FaceTrack(sequence), video_options(options), audio, where);
}

Result<std::string> face_html(const FapSequence& sequence, const PictureOptions& options, const AudioInput* audio,
                              const std::string& title, const std::string& where, PreviewView view,
                              std::string head_glb) {
  const FaceTrack track(sequence);
  Result<std::string> video = encode_webm(track, video_options(options), audio, where);
  if (!video) return video.error();
  PreviewOptions page;
  page.width = options.width;
  page.height = options.height;
  page.frame_rate = options.frame_rate > 0 ? options.frame_rate : track.fps();
  page.title = title;
  page.sound = audio != nullptr;
  page.view = view;
  page.head_glb = std::move(head_glb);
  return preview_page(track, *video, page);
}

}  // namespace fapc::face

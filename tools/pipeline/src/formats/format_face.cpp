// The face outputs: .png (a frame or a contact sheet), .webm (VP9 video) and .html (the preview
// page), drawn by fapc::face from the frames of any input (docs/render.md).
#include <filesystem>
#include <optional>
#include <utility>

#include "fapc/face/pictures.hpp"
#include "fapc/face/webm.hpp"
#include "fapc/head3d/gltf_writer.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

namespace {

face::PictureOptions picture_options(const ConvertOptions& options, const std::string& path) {
  const PictureSettings& p = options.picture;
  face::PictureOptions picture{p.width, p.height, p.frame, p.time, p.sheet, p.frame_rate, p.points, options.limits, {}};
  if (options.progress)
    picture.progress = [&options, path](std::int64_t done, std::int64_t total) {
      options.progress("encoding " + path, done, total);
    };
  return picture;
}

Result<std::string> write_png(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  return face::face_png(loaded.frames, picture_options(options, path), path);
}

// The voice beside the face, as the video writer takes it; none when the input has none.
std::optional<face::AudioInput> voice_of(const Loaded& loaded) {
  if (!loaded.audio || loaded.audio->samples.empty()) return std::nullopt;
  face::AudioInput voice;
  voice.sample_rate = loaded.audio->sample_rate;
  voice.channels = 1;
  voice.start = loaded.audio->start;
  voice.samples.reserve(loaded.audio->samples.size());
  for (const std::int16_t s : loaded.audio->samples) voice.samples.push_back(static_cast<float>(s) / 32768.0F);
  return voice;
}

// A video's limits on the length (OutputFormat::check_length): the errors about the length at
// `ends`, those about the options at the output.
Status video_takes(std::int64_t frames, int fps, const Location& ends, const std::string& path,
                   const ConvertOptions& options) {
  const PictureSettings& p = options.picture;
  return face::check_video(frames, fps, face::VideoOptions{p.width, p.height, p.frame_rate, options.limits, {}},
                           Location::whole_file(path), ends);
}

// The same of frames already loaded (a .fap, an .fba), their length placed at the input.
Status video_takes(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  const std::vector<FapFrame>& frames = loaded.frames.frames;
  return video_takes(frames.empty() ? 0 : frames.back().number + 1, loaded.frames.fps,
                     Location::whole_file(loaded.named(path)), path, options);
}

Result<std::string> write_webm(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  if (Status fits = video_takes(loaded, path, options); !fits) return fits.error();
  const auto voice = voice_of(loaded);
  return face::face_webm(loaded.frames, picture_options(options, path), voice ? &*voice : nullptr, path);
}

// The page, with the 3D head's .glb (named by FAP: the page plays it, no avatar reads it) when
// --view asks for the 3D view.
Result<std::string> write_html(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  if (Status fits = video_takes(loaded, path, options); !fits) return fits.error();
  const auto voice = voice_of(loaded);
  const std::string& v = options.picture.view;
  const face::PreviewView view = v == "3d"     ? face::PreviewView::three_d
                                 : v == "both" ? face::PreviewView::both
                                               : face::PreviewView::two_d;
  std::string glb;
  if (view != face::PreviewView::two_d) {
    Result<std::string> head = head3d::head_gltf(loaded.frames, head3d::GltfOptions{}, path);
    if (!head) return head.error();
    glb = std::move(*head);
  }
  return face::face_html(loaded.frames, picture_options(options, path), voice ? &*voice : nullptr,
                         std::filesystem::path(path).stem().string(), path, view, std::move(glb));
}

// A picture of the face, and with the video and the page the voice when the input has one.
OutputFormat face_output(OutputFormat format, bool with_voice) {
  format.picture = true;
  format.uses_audio = with_voice;
  return format;
}

// A video: its length checked before a script's frames are made.
OutputFormat video_output(OutputFormat format) {
  format = face_output(std::move(format), true);
  format.check_length = [](std::int64_t frames, int fps, const Location& ends, const std::string& path,
                           const ConvertOptions& options) { return video_takes(frames, fps, ends, path, options); };
  return format;
}

}  // namespace

OutputFormat png_output() { return face_output({"png", {".png"}, write_png}, false); }
OutputFormat webm_output() { return video_output({"webm", {".webm"}, write_webm}); }
OutputFormat html_output() { return video_output({"html", {".html"}, write_html}); }

}  // namespace fapc::pipeline::builtin

// The face outputs: .png (a frame or a contact sheet), .webm (VP9 video) and .html (the preview
// page), drawn by fapc::face from the frames of any input (docs/render.md).
#include <filesystem>

#include "fapc/face/pictures.hpp"
#include "fapc/face/webm.hpp"
#include "formats.hpp"

namespace fapc::pipeline::builtin {

namespace {

face::PictureOptions picture_options(const ConvertOptions& options) {
  const PictureSettings& p = options.picture;
  return face::PictureOptions{p.width, p.height, p.frame, p.time, p.sheet, p.frame_rate, p.points};
}

Result<std::string> write_png(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  return face::face_png(loaded.frames, picture_options(options), path);
}

Result<std::string> write_webm(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  return face::face_webm(loaded.frames, picture_options(options), path);
}

Result<std::string> write_html(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  return face::face_html(loaded.frames, picture_options(options),
                         std::filesystem::path(path).stem().string(), path);
}

}  // namespace

OutputFormat png_output() { return {"png", {".png"}, write_png}; }
OutputFormat webm_output() { return {"webm", {".webm"}, write_webm}; }
OutputFormat html_output() { return {"html", {".html"}, write_html}; }

}  // namespace fapc::pipeline::builtin

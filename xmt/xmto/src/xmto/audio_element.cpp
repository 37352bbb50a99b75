#include "xmto/audio_element.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "fapc/codec/file_io.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/transcoder/speech.hpp"
#include "fapc/transcoder/wav.hpp"
#include "fapc/xml/clock_value.hpp"
#include "fapc/xml/text.hpp"
#include "fapc/xmto/codes.hpp"
#include "fml/speech_visemes.hpp"

namespace fapc::xmto {
namespace {

namespace fs = std::filesystem;

// An error of something the element names, placed at the element (its src attribute).
Diagnostic at_src(const xml::XmlDocument& doc, const xmlNode* element, const std::string& name,
                  const Diagnostic& problem) {
  const Location where = doc.where(element, "src");
  return retold(problem, where, "audio '" + name + "': " + problem.message, doc.line_text(where.line));
}

// The file's bytes, refused before reading when larger than the limit.
Result<std::string> read_bounded(const xml::XmlDocument& doc, const xmlNode* element, const std::string& name,
                                 const std::string& path, const XmtoOptions& options) {
  std::error_code error;
  const auto size = fs::file_size(path, error);
  if (!error && static_cast<std::int64_t>(size) > options.limits.max_decompressed_bytes) {
    Limits limits;
    limits.max_decompressed_bytes = options.limits.max_decompressed_bytes;
    Diagnostic d = limit_error(doc.where(element, "src"), "audio '" + name + "' is " + std::to_string(size) + " bytes",
                               Limit::decompressed_bytes, limits);
    d.source_line = doc.line_text(d.where.line);
    return d;
  }
  Result<std::string> bytes = read_file_bytes(path);
  if (!bytes) return at_src(doc, element, name, bytes.error());
  return bytes;
}

// `name` through the include rules, refused at the element's src with the line shown.
Result<std::string> allowed(const xml::XmlDocument& doc, const xmlNode* element, const std::string& name,
                            const XmtoOptions& options) {
  Result<std::string> path = resolve_include(name, doc.file(), options.includes, doc.where(element, "src"));
  if (path) return path;
  Diagnostic refused = path.error();
  refused.source_line = doc.line_text(refused.where.line);
  return refused;
}

}  // namespace

Result<Recording> load_recording(const xml::XmlDocument& doc, const xmlNode* element, const XmtoOptions& options,
                                 Diagnostics& warnings) {
  const auto src = xml::attribute(element, "src");
  if (!src) return doc.error(codes::xmto::missing_attribute, element, "audio needs src naming a WAV file");
  std::string_view trimmed = xml::trim(*src);
  if (trimmed.starts_with("file:")) trimmed.remove_prefix(5);
  const std::string name(trimmed);
  if (name.empty()) return doc.error(codes::xmto::bad_source, element, "src", "src is empty");
  if (name.find("://") != std::string::npos)
    return doc.error(codes::xmto::bad_source, element, "src",
                     "src '" + name + "': only local files can be placed, not URLs");
  Result<std::string> path = allowed(doc, element, name, options);
  if (!path) return path.error();
  Result<std::string> bytes = read_bounded(doc, element, name, *path, options);
  if (!bytes) return bytes.error();
  Result<AudioClip> sound = read_wav(*bytes, *path);
  if (!sound) return at_src(doc, element, name, sound.error());
  sound->begin = 0;
  sound->source = doc.where(element);

  Recording recording;
  recording.wav_path = *path;
  double length = static_cast<double>(sound->samples.size()) / sound->sample_rate;
  if (const auto clip_end = xml::attribute(element, "clipEnd")) {
    const auto seconds = xml::parse_clock_value(*clip_end);
    if (!seconds)
      return doc.error(codes::xmto::bad_time, element, "clipEnd",
                       "clipEnd '" + std::string(*clip_end) + "' is not a clock value");
    length = std::min(length, *seconds);
  }
  recording.timeline.explicit_end = length;
  recording.timeline.end_source = doc.where(element);

  // The phonemes of the recording, when a .pho of the same stem lies beside it: read through the
  // include rules too (a symbolic link must not lead outside the allowed folders).
  const std::string pho_name = fs::path(name).replace_extension(".pho").string();
  std::error_code error;
  if (fs::is_regular_file(fs::path(*path).replace_extension(".pho"), error)) {
    Result<std::string> pho_path = allowed(doc, element, pho_name, options);
    if (!pho_path) return pho_path.error();
    Result<std::string> text = read_bounded(doc, element, pho_name, *pho_path, options);
    if (!text) return text.error();
    Result<fml::Speech> speech = fml::visemes_from_pho(*text, *pho_path, warnings);
    if (!speech) return speech.error();
    recording.pho_path = *pho_path;
    recording.timeline.clips =
        coarticulated_viseme_clips(std::move(speech->visemes), 1.0, options.speech.coarticulation, doc.where(element));
  }
  recording.timeline.audio.push_back(std::move(*sound));
  return recording;
}

}  // namespace fapc::xmto

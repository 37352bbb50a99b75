#include "bml/recorded_speech.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bml/sync_ref.hpp"
#include "fapc/bml/codes.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/transcoder/wav.hpp"
#include "fapc/xml/text.hpp"

namespace fapc::bml {
namespace {

namespace fs = std::filesystem;

// The marks of the speech's text (sync, tm or mark elements), each with its recorded time.
// Other elements in the text (prosody marks) are said once: the recording is what is heard.
Status read_marks(const xml::XmlDocument& doc, const xmlNode* text, const ReaderOptions& options, Diagnostics& warnings,
                  SpokenText& out) {
  bool said = false;
  for (const xmlNode* mark : doc.children(text)) {
    const std::string_view name = xml::local_name(mark);
    if (name != "sync" && name != "tm" && name != "mark") {
      if (!said) {
        Diagnostic w = doc.warning(mark, "<" + std::string(name) +
                                             "> in recorded speech is not read: the recording is what "
                                             "is heard, and only the marks' times are taken");
        w.code = codes::bml::speech_markup_skipped.name;
        warnings.push_back(std::move(w));
        said = true;
      }
      continue;
    }
    const std::string id(xml::trim(xml::attribute(mark, "id").value_or("")));
    if (id.empty())
      return doc.error(codes::bml::missing_attribute, mark, "<" + std::string(name) + "> in speech needs an id");
    const auto time_text = xml::attribute(mark, "time");
    if (!time_text)
      return doc.error(codes::bml::missing_attribute, mark,
                       "a mark of recorded speech needs time, seconds from the speech's start (the recording's "
                       "audio says nothing about where its words are)");
    const auto time = xml::decimal(xml::trim(*time_text));
    if (!time || !std::isfinite(*time) || *time < 0)
      return doc.error(codes::bml::bad_value, mark, "time",
                       "time '" + *time_text + "' is not a number of seconds from 0 on");
    if (*time > options.speech.max_seconds) {
      return doc.error(codes::limit::frames, mark, "time",
                       "mark '" + id + "' at " + seconds_text(*time) + ": the speech would last more than " +
                           seconds_text(options.speech.max_seconds) +
                           " (the frame limit at this frame rate; raise it with --max-frames)");
    }
    if (!out.mark_times.empty() && *time < out.mark_times.back())
      return doc.error(codes::bml::marks_out_of_order, mark, "time",
                       "mark '" + id + "' at " + seconds_text(*time) + " comes before the mark before it ('" +
                           out.mark_ids.back() + "' at " + seconds_text(out.mark_times.back()) + ")");
    out.mark_ids.push_back(id);
    out.mark_times.push_back(*time);
    out.duration = std::max(out.duration, *time);
  }
  return ok_status();
}

// The file's audio, or no samples (a warning) when it does not exist.
Status read_audio(const xml::XmlDocument& doc, const xmlNode* description, const ReaderOptions& options,
                  Diagnostics& warnings, std::vector<std::string>& recordings, SpokenText& out) {
  const xmlNode* file = nullptr;
  for (const xmlNode* child : doc.children(description))
    if (xml::local_name(child) == "file") file = child;
  const std::string ref(file != nullptr ? xml::trim(xml::attribute(file, "ref").value_or("")) : "");
  if (ref.empty()) {
    Diagnostic w =
        doc.warning(file != nullptr ? file : description,
                    "recorded speech names no audio file (<file ref=\"NAME\"/>): its marks keep their times, "
                    "with no voice");
    w.code = codes::bml::recorded_audio_missing.name;
    warnings.push_back(std::move(w));
    return ok_status();
  }
  // NVBG writes the file's stem: the audio is NAME.wav next to the document.
  const std::string name = fs::path(ref).has_extension() ? ref : ref + ".wav";
  Result<std::string> path = resolve_include(name, doc.file(), options.includes, doc.where(file, "ref"));
  if (!path) {
    Diagnostic refused = path.error();
    refused.source_line = doc.line_text(refused.where.line);
    return refused;
  }
  std::error_code error;
  // Only a name that is not there is missing; a directory or FIFO there is refused by
  // read_file_bytes (before it could block).
  if (!fs::exists(*path, error)) {
    Diagnostic w = doc.warning(file, "ref",
                               "the recording '" + name +
                                   "' is not next to the document: the speech keeps "
                                   "its recorded times, with no voice");
    w.code = codes::bml::recorded_audio_missing.name;
    warnings.push_back(std::move(w));
    return ok_status();
  }
  // Refused by its size before it is read (a recording is never compressed, so its size is its bytes).
  if (const auto size = fs::file_size(*path, error);
      !error && static_cast<std::int64_t>(size) > options.limits.max_decompressed_bytes) {
    Diagnostic d = limit_error(doc.where(file, "ref"), "recording '" + name + "' is " + std::to_string(size) + " bytes",
                               Limit::decompressed_bytes, options.limits);
    d.source_line = doc.line_text(d.where.line);
    return d;
  }
  Result<std::string> bytes = read_file_bytes(*path, options.limits);
  if (!bytes) {
    const Location at = doc.where(file, "ref");
    return retold(bytes.error(), at, "recording '" + name + "': " + bytes.error().message, doc.line_text(at.line));
  }
  Result<AudioClip> audio = read_wav(*bytes, *path);
  if (!audio) {  // placed at the reference, saying what is wrong where in the file
    const Location at = doc.where(file, "ref");
    return retold(
        audio.error(), at,
        "recording '" + name + "': " + audio.error().message +
            (audio.error().where.byte_offset >= 0 ? " (at byte " + std::to_string(audio.error().where.byte_offset) + ")"
                                                  : std::string()),
        doc.line_text(at.line));
  }
  if (static_cast<std::int64_t>(audio->samples.size()) > options.limits.max_audio_samples) {
    Diagnostic d = limit_error(doc.where(file, "ref"),
                               "recording '" + name + "' holds " + std::to_string(audio->samples.size()) + " samples",
                               Limit::audio_samples, options.limits);
    d.source_line = doc.line_text(d.where.line);
    return d;
  }
  audio->source = doc.where(file);
  out.duration = std::max(out.duration, static_cast<double>(audio->samples.size()) / audio->sample_rate);
  out.audio = std::move(*audio);
  recordings.push_back(*path);
  return ok_status();
}

}  // namespace

const xmlNode* audio_description(const xml::XmlDocument& doc, const xmlNode* speech) {
  for (const xmlNode* child : doc.children(speech))
    if (xml::local_name(child) == "description" &&
        xml::trim(xml::attribute(child, "type").value_or("")).starts_with("audio/"))
      return child;
  return nullptr;
}

Result<SpokenText> recorded_speech(const xml::XmlDocument& doc, const xmlNode* speech, const xmlNode* description,
                                   const ReaderOptions& options, Diagnostics& warnings,
                                   std::vector<std::string>& recordings) {
  SpokenText out;
  out.recorded = true;
  for (const xmlNode* child : doc.children(speech))
    if (xml::local_name(child) == "text")
      if (Status marks = read_marks(doc, child, options, warnings, out); !marks) return marks.error();
  if (Status audio = read_audio(doc, description, options, warnings, recordings, out); !audio) return audio.error();
  return out;
}

}  // namespace fapc::bml

// talk: its text spoken by the engine (or the letter table), or an MBROLA .pho file's visemes.
#include <algorithm>
#include <filesystem>

#include "fapc/codec/file_io.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fml/fml_reader.hpp"
#include "fml/speech_visemes.hpp"

namespace fapc::fml::reading {

std::optional<ScheduleNode> FmlReader::talk(const xmlNode* node, const FmlTiming& timing) {
  check_attributes(node, kTiming, {"file", "ev_val", "event_value", "lang", "voice"});
  for (const xmlNode* child : xml::element_children(node)) {
    unknown(child, "inside talk is skipped with the text in it: talk says only its own text");
  }
  const std::string text = trim(xml::text_content(node));
  const auto file = xml::attribute(node, "file");
  if (file && !text.empty()) {
    fail(doc_.error(codes::fml::talk_text_and_file, node, "file", "talk has both text and file; give one"));
    return std::nullopt;
  }
  FmlLeaf leaf;
  leaf.kind = FmlLeaf::Kind::talk;
  leaf.talk = std::make_unique<FmlTalk>();
  if (file) {
    auto speech = phonemes(node, trim(*file));
    if (!speech) return std::nullopt;
    if (speech->visemes.empty() && speech->duration == 0) {
      return as_wait(node, timing,
                     doc_.warning(node, "file",
                                  "talk file '" + *file +
                                      "' is not an MBROLA .pho "
                                      "phoneme file: fapc has no speech recogniser, so "
                                      "this talk is silent (it waits)"));
    }
    leaf.talk->speech = std::move(*speech);
  } else {
    if (text.empty()) {
      fail(
          doc_.error(codes::fml::talk_without_text, node, "talk needs text to say or a phoneme file (file=\"x.pho\")"));
      return std::nullopt;
    }
    if (!speak(node, text, *leaf.talk)) return std::nullopt;
  }
  // The talk lasts until its sound ends and the mouth is back at neutral.
  FmlTalk& talk = *leaf.talk;
  talk.natural = talk.speech.duration;
  for (const Clip& clip : talk_timeline(talk, leaf.where, talk.speech.duration, options_.speech.coarticulation).clips)
    talk.natural = std::max(talk.natural, clip.end);
  const double intrinsic = talk.natural;
  return add_leaf(node, std::move(leaf), move_timing(timing, intrinsic));
}

// Talk text: spoken by the engine, or (built without one) the letter approximation, with a
// warning once per document.
bool FmlReader::speak(const xmlNode* node, const std::string& text, FmlTalk& talk) {
  if (!options_.speech.synthesize) {
    once_.report("no speech engine", doc_.warning(node,
                                                  "no speech engine (fapc built with FAPC_SPEECH=OFF, or none "
                                                  "given): talk text becomes visemes by the letter table, with "
                                                  "no voice"));
    std::string skipped;
    talk.speech = visemes_from_text(text, options_.speech.words_per_minute * 12 / 175, skipped);
    if (!skipped.empty()) {
      once_.report("skipped " + skipped, doc_.warning(node, "talk: the characters '" + skipped +
                                                                "' have no letter-to-viseme rule and are silent"));
    }
    return true;
  }
  SpeechRequest request;
  request.text = text;
  request.language = talk_language(node);
  request.voice = xml::attribute(node, "voice") ? trim(*xml::attribute(node, "voice"))
                  : !model_voice_.empty()       ? model_voice_
                                                : options_.speech.voice;
  request.words_per_minute = options_.speech.words_per_minute;
  request.where = xml::attribute(node, "lang") ? doc_.where(node, "lang") : doc_.where(node);
  // The document's speech budget, before the engine runs (docs/security.md): text bytes, then
  // seconds as estimated from the text; the engine then stops at the seconds left.
  const Limits& limits = options_.limits;
  speech_text_bytes_ += static_cast<std::int64_t>(text.size());
  if (speech_text_bytes_ > limits.max_speech_text_bytes) {
    fail(placed(limit_error(doc_.where(node),
                            "the talk text of this document reaches " + std::to_string(speech_text_bytes_) + " bytes",
                            Limit::speech_text, limits)));
    return false;
  }
  const double left = limits.max_speech_seconds - speech_seconds_;
  const double estimate = estimated_speech_seconds(text, request.words_per_minute);
  if (estimate > left) {
    fail(placed(limit_error(
        doc_.where(node),
        "the speech of this document would last at least " + seconds_text(speech_seconds_ + estimate) + " s",
        Limit::speech_seconds, limits)));
    return false;
  }
  request.max_seconds = std::min(left, options_.speech.max_seconds);
  Result<Utterance> spoken = options_.speech.synthesize(request);
  if (!spoken && spoken.error().kind == ErrorKind::limit_exceeded) {
    fail(placed(left <= options_.speech.max_seconds
                    ? limit_error(doc_.where(node),
                                  "the speech of this document would last more than " +
                                      seconds_text(limits.max_speech_seconds) + " s",
                                  Limit::speech_seconds, limits)
                    : make_error(codes::limit::frames, doc_.where(node),
                                 "the speech would last more than " + seconds_text(options_.speech.max_seconds) +
                                     " s (the frame limit, --max-frames, at the frame rate)")));
    return false;
  }
  if (!spoken) {
    Diagnostic refused = spoken.error();
    refused.source_line = doc_.line_text(refused.where.line);
    fail(std::move(refused));
    return false;
  }
  for (Diagnostic& warning : spoken->warnings) {
    warning.source_line = doc_.line_text(warning.where.line);
    result_.warnings.push_back(std::move(warning));
  }
  if (std::find(result_.languages.begin(), result_.languages.end(), request.language) == result_.languages.end())
    result_.languages.push_back(request.language);
  talk.speech.visemes = viseme_spans(spoken->phonemes);
  talk.speech.duration = spoken->duration;
  talk.audio = std::move(spoken->audio);
  speech_seconds_ += spoken->duration;
  return true;
}

// The talk's `lang`, else the xml:lang in force there (on it or an ancestor), else the model's
// character lang, else the options' (--voice).
std::string FmlReader::talk_language(const xmlNode* node) const {
  if (const auto lang = xml::attribute(node, "lang")) return trim(*lang);
  if (xmlChar* inherited = xmlNodeGetLang(node)) {
    std::string lang = trim(reinterpret_cast<const char*>(inherited));
    xmlFree(inherited);
    if (!lang.empty()) return lang;
  }
  return !model_language_.empty() ? model_language_ : options_.speech.language;
}

// A .pho file's visemes; an empty speech for other files (the caller warns).
std::optional<Speech> FmlReader::phonemes(const xmlNode* node, const std::string& name) {
  if (std::filesystem::path(name).extension() != ".pho") return Speech{};
  Result<std::string> allowed = resolve_include(name, doc_.file(), options_.includes, doc_.where(node, "file"));
  if (!allowed) {
    Diagnostic refused = allowed.error();
    refused.source_line = doc_.line_text(refused.where.line);
    fail(std::move(refused));
    return std::nullopt;
  }
  const std::string& resolved = *allowed;
  Result<std::string> text = options_.read_file ? options_.read_file(resolved) : read_file_bytes(resolved);
  if (!text) {
    fail(doc_.error(codes::fml::talk_file_unreadable, node, "file",
                    "talk file '" + name + "': " + text.error().message));
    return std::nullopt;
  }
  result_.phoneme_files.push_back(resolved);
  Result<Speech> speech = visemes_from_pho(*text, resolved, result_.warnings);
  if (!speech) {
    fail(speech.error());
    return std::nullopt;
  }
  return std::move(*speech);
}

}  // namespace fapc::fml::reading

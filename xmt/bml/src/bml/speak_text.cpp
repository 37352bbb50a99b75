#include "bml/speak_text.hpp"

#include <algorithm>

#include "fapc/bml/codes.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/transcoder/speech.hpp"
#include "fml/speech_visemes.hpp"

namespace fapc::bml {
namespace {

// The onset of the first word that starts at or after `offset`: the first sounding phoneme from
// the engine's word time on (the word event comes before a pause that precedes the word).
double onset_after(const Utterance& spoken, std::size_t offset) {
  const auto word = std::find_if(spoken.words.begin(), spoken.words.end(),
                                 [&](const SpokenWord& w) { return w.text_offset >= offset; });
  if (word == spoken.words.end()) return spoken.duration;
  for (const SpokenPhoneme& p : spoken.phonemes)
    if (p.begin + 1e-9 >= word->begin && !p.name.empty() && p.name[0] != '_') return p.begin;
  return word->begin;
}

}  // namespace

Result<SpokenText> speak(const MarkedText& text, const ReaderOptions& options, const Location& where,
                         Diagnostics& warnings, SpeakingSoFar& so_far) {
  const Limits& limits = options.limits;
  so_far.text_bytes += static_cast<std::int64_t>(text.text.size());
  if (so_far.text_bytes > limits.max_speech_text_bytes)
    return limit_error(where,
                       "the speech text of this document reaches " + std::to_string(so_far.text_bytes) + " bytes",
                       Limit::speech_text, limits);
  const double left = limits.max_speech_seconds - so_far.seconds;
  const double estimate = estimated_speech_seconds(text.text, options.speech.words_per_minute);
  if (estimate > left)
    return limit_error(where,
                       "the speech of this document would last at least " +
                           std::to_string(static_cast<long long>(so_far.seconds + estimate)) + " s",
                       Limit::speech_seconds, limits);
  SpokenText out;
  out.mark_ids = text.mark_ids;
  if (!options.speech.synthesize) {
    if (!so_far.warned_no_engine) {
      so_far.warned_no_engine = true;
      warnings.push_back(make_warning(codes::bml::no_speech_engine, where,
                                      "no speech engine in this build: speech text becomes visemes by the letter "
                                      "table, silent, and sync marks fall in proportion to the text"));
    }
    std::string skipped;
    fml::Speech speech = fml::visemes_from_text(text.text, options.speech.words_per_minute * 12 / 175, skipped);
    out.visemes = std::move(speech.visemes);
    out.duration = speech.duration;
    so_far.seconds += speech.duration;
    for (std::size_t offset : text.mark_offsets)
      out.mark_times.push_back(text.text.empty() ? 0.0 : out.duration * double(offset) / double(text.text.size()));
    return out;
  }
  SpeechRequest request;
  request.text = text.text;
  request.language = options.speech.language;
  request.voice = options.speech.voice;
  request.words_per_minute = options.speech.words_per_minute;
  request.max_seconds = std::min(options.speech.max_seconds, left);
  request.where = where;
  Result<Utterance> spoken = options.speech.synthesize(request);
  if (!spoken && spoken.error().kind == ErrorKind::limit_exceeded && left < options.speech.max_seconds)
    return limit_error(where,
                       "the speech of this document would last more than " +
                           std::to_string(static_cast<long long>(limits.max_speech_seconds)) + " s",
                       Limit::speech_seconds, limits);
  if (!spoken) return spoken.error();
  so_far.seconds += spoken->duration;
  for (Diagnostic& w : spoken->warnings) warnings.push_back(std::move(w));
  out.visemes = viseme_spans(spoken->phonemes);
  out.duration = spoken->duration;
  for (std::size_t offset : text.mark_offsets) out.mark_times.push_back(onset_after(*spoken, offset));
  out.audio = std::move(spoken->audio);
  return out;
}

}  // namespace fapc::bml

// Speech as the timeline sees it (docs/speech.md): what a text-to-speech engine is asked for and
// what it answers (samples plus timed phonemes already mapped to MPEG-4 visemes), and the
// coarticulation rule that turns viseme spans into overlapping, cross-fading viseme.* clips.
// The engine itself (fapc::speech, GPL-3.0+ through libespeak-ng) lives outside this library and
// is handed in as a Synthesizer, so fapc::transcoder never links it.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/timeline/audio.hpp"
#include "fapc/timeline/timeline.hpp"

namespace fapc {

// One MPEG-4 viseme (1..14, fap_table.hpp viseme_name) held over [begin, end) seconds.
struct VisemeSpan {
  int viseme = 0;
  double begin = 0;
  double end = 0;
  double weight = 1;  // 0..1: how far the mouth goes (a recorded viseme's articulation)
  friend bool operator==(const VisemeSpan&, const VisemeSpan&) = default;
};

// One phoneme as the engine spoke it: its mnemonic, its time, and its viseme (0: silence or no
// mouth shape of its own).
struct SpokenPhoneme {
  std::string name;
  double begin = 0;
  double end = 0;
  int viseme = 0;
  friend bool operator==(const SpokenPhoneme&, const SpokenPhoneme&) = default;
};

struct SpeechRequest {
  std::string text;             // UTF-8
  std::string language = "en";  // an engine language ("en", "en-us", "fr", "de", ...)
  std::string voice;            // a voice variant ("f3", "m1", "klatt", ...); empty: the default
  double words_per_minute = 175;
  double max_seconds = 3600;  // longer speech is a limit_exceeded error
  Location where;             // the element that asked, for errors and warnings
};

// Where one word of the request's text begins to be spoken (BML sync marks sit at words).
struct SpokenWord {
  std::size_t text_offset = 0;  // byte offset of the word in SpeechRequest::text
  double begin = 0;             // seconds: the engine's time for the word
  friend bool operator==(const SpokenWord&, const SpokenWord&) = default;
};

struct Utterance {
  AudioClip audio;                      // begin 0: the caller places it
  std::vector<SpokenPhoneme> phonemes;  // in time order, covering [0, duration)
  std::vector<SpokenWord> words;        // in text order; empty when the engine gives no word events
  double duration = 0;
  Diagnostics warnings;  // unknown phonemes and the like
};

// A low estimate of how long `text` takes to say at `words_per_minute`, from its letters and
// digits alone, made before any synthesis (docs/speech.md, "Hostile text"): honest text is said
// at some 11 to 16 letters a second at 175 words per minute; the estimate takes 24, so that it
// refuses up front only what is surely too long, and the synthesis counts the rest.
double estimated_speech_seconds(std::string_view text, double words_per_minute);

// Synthesises one request; errors (unknown language or voice) name request.where.
using Synthesizer = std::function<Result<Utterance>(const SpeechRequest&)>;

// The viseme spans of an utterance: consecutive phonemes of one viseme merge; a phoneme without
// a mouth shape of its own (viseme 0 that is not a pause, such as h) takes the shape of the next
// spoken phoneme, else the previous one; pauses (names starting with '_') are gaps.
std::vector<VisemeSpan> viseme_spans(const std::vector<SpokenPhoneme>& phonemes);

// The coarticulation rule (docs/speech.md): each span becomes one viseme clip of weight 63 (times
// the span's weight) whose edges are linear cross-fades of `fade` seconds centred on the span's boundaries, so
// neighbours overlap and FAP 1 blends them (viseme_select1/2, viseme_blend); a fade is never longer than the shorter of
// the two spans it joins, and at silence the weight falls to 0 (neutral). The first fade-in starts no earlier than time
// 0; the last fade-out may end fade/2 after the last span. Spans shorter than `min_hold` are first widened to it around
// their centre (taking the time from their neighbours), so a short closure such as a p still shows on a frame.
struct Coarticulation {
  double fade = 0.06;      // seconds
  double min_hold = 0.04;  // seconds; one frame at 25 fps
};

// `stretch` scales the spans' times first (a talk given a longer duration than its speech).
std::vector<Clip> coarticulated_viseme_clips(std::vector<VisemeSpan> spans, double stretch, const Coarticulation& rule,
                                             const Location& where);

}  // namespace fapc

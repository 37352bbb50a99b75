// eSpeak NG in synchronous mode: espeak_Synth calls back with blocks of samples and the events
// of those samples, phoneme events included (espeakINITIALIZE_PHONEME_EVENTS). eSpeak NG keeps
// its voice, rate, callback and synthesis state in globals, so one mutex covers every use of it.
// This process only ever initialises it and lists its voices, to check requests: each utterance is
// spoken in a child of the speaker process (speaker_process.hpp), which initialised the engine
// once and never speaks itself, so every utterance starts from the same state whatever was said
// before, in this process or another (docs/speech.md, "Every utterance alike").
#include "fapc/speech/engine.hpp"

#ifdef FAPC_HAVE_ESPEAK

#include <espeak-ng/speak_lib.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>

#include "engine_messages.hpp"
#include "engine_output.hpp"
#include "fapc/speech/codes.hpp"
#include "fapc/speech/phoneme_visemes.hpp"
#include "fapc/speech/speakable_text.hpp"
#include "speaker_process.hpp"

namespace fapc::speech {
namespace {

std::mutex& engine_mutex() {
  static std::mutex m;
  return m;
}

// What the child's espeak_Synth calls collect into, reached through `collecting` (a block of
// samples may come with no event, so user_data cannot be relied on).
struct Collect {
  EngineOutput output;
  std::size_t max_samples = 0;
};

Collect* collecting = nullptr;

int on_samples(short* wav, int count, espeak_EVENT* events) {
  Collect* into = collecting;
  if (into == nullptr) return 0;
  for (espeak_EVENT* e = events; e != nullptr && e->type != espeakEVENT_LIST_TERMINATED; ++e) {
    if (e->type == espeakEVENT_PHONEME) {
      char name[9] = {};
      std::memcpy(name, e->id.string, 8);
      into->output.phonemes.emplace_back(name, e->audio_position);
    } else if (e->type == espeakEVENT_WORD) {
      into->output.words.emplace_back(e->text_position, e->audio_position);
    }
  }
  if (wav == nullptr || count <= 0) return 0;
  std::vector<std::int16_t>& samples = into->output.samples;
  if (samples.size() + static_cast<std::size_t>(count) > into->max_samples) {
    into->output.stop = EngineOutput::Stop::too_long;
    return 1;  // stop the synthesis
  }
  samples.insert(samples.end(), wav, wav + count);
  return 0;
}

struct Engine {
  int sample_rate = 0;
  std::filesystem::path data;  // espeak-ng-data: voices/!v holds the variants
  // The names of eSpeak NG's own voices (lower case): every language each lists, and the last
  // part of its identifier ("gmw/en-GB-x-rp": "en-gb-x-rp"). MBROLA voices ("mb/mb-en1") are not
  // among them: loading one makes eSpeak NG fork the first program called `mbrola` on the PATH,
  // so a script would choose a program to run. Their names are kept apart to say so.
  std::set<std::string> own;
  std::set<std::string> mbrola;
};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void list_voices(Engine& e) {
  const espeak_VOICE** voices = espeak_ListVoices(nullptr);
  for (const espeak_VOICE** v = voices; v != nullptr && *v != nullptr; ++v) {
    const std::string identifier = (*v)->identifier != nullptr ? (*v)->identifier : "";
    const bool mbrola = identifier.rfind("mb/", 0) == 0;
    std::set<std::string>& into = mbrola ? e.mbrola : e.own;
    into.insert(lower(identifier.substr(identifier.rfind('/') + 1)));
    if (mbrola) continue;  // its languages ("en") are eSpeak NG's own voices' too
    // languages: a priority byte, then a NUL-terminated name, repeated; a 0 priority ends it.
    for (const char* p = (*v)->languages; p != nullptr && *p != 0; p += std::strlen(p + 1) + 2)
      into.insert(lower(p + 1));
  }
  // espeak_ListVoices(NULL) leaves MBROLA voices out: their files are named mb-*.
  for (const std::string& name : e.own)
    if (name.rfind("mb-", 0) == 0) e.mbrola.insert(name);
  for (const std::string& name : e.mbrola) e.own.erase(name);
}

// Initialised once, under the mutex; sample_rate 0 when eSpeak NG could not start.
const Engine& started() {
  static const Engine engine = [] {
    Engine e;
    e.sample_rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr,
                                      espeakINITIALIZE_PHONEME_EVENTS | espeakINITIALIZE_DONT_EXIT);
    if (e.sample_rate <= 0) e.sample_rate = 0;
    const char* path = nullptr;
    espeak_Info(&path);
    if (path != nullptr) e.data = path;
    espeak_SetSynthCallback(on_samples);
    if (e.sample_rate > 0) list_voices(e);
    return e;
  }();
  return engine;
}

bool plain_name(const std::string& s) {
  return !s.empty() && s.size() <= 40 && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
  });
}

// The synthesis itself, run in the child (speak() checked the names and the rate). srand: the
// breathy and Klatt voices draw noise from rand(), whose state the child would otherwise take
// from whatever its parent did with it.
void spoken_in_this_process(const EngineRequest& request, EngineOutput& into) {
  std::srand(1);
  if (espeak_SetVoiceByName(request.language.c_str()) != EE_OK) {
    into.stop = EngineOutput::Stop::language_refused;
    return;
  }
  if (!request.voice.empty() && espeak_SetVoiceByName((request.language + "+" + request.voice).c_str()) != EE_OK) {
    into.stop = EngineOutput::Stop::voice_refused;
    return;
  }
  espeak_SetParameter(espeakRATE, request.words_per_minute, 0);
  // The text in bounded, neutralised pieces (speakable_text.hpp), spoken one after the other:
  // each piece's phonemes are moved by the audio before it.
  const int sample_rate = started().sample_rate;
  for (const std::string& piece : speakable_pieces(request.text)) {
    const std::size_t first_phoneme = into.phonemes.size();
    const auto offset_ms = static_cast<int>(into.samples.size() * 1000 / static_cast<std::size_t>(sample_rate));
    const espeak_ERROR status =
        espeak_Synth(piece.c_str(), piece.size() + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, nullptr, nullptr);
    for (std::size_t i = first_phoneme; i < into.phonemes.size(); ++i) into.phonemes[i].second += offset_ms;
    if (into.stop != EngineOutput::Stop::spoken) return;
    if (status != EE_OK) {
      into.stop = EngineOutput::Stop::synth_failed;
      into.synth_status = static_cast<std::int32_t>(status);
      return;
    }
  }
}

// What the speaker's child runs for each request.
std::string serve(std::string_view bytes) {
  const std::optional<EngineRequest> request = decode_engine_request(bytes);
  if (!request) ::_exit(6);
  Collect collect;
  collect.max_samples = request->max_samples;
  collecting = &collect;
  spoken_in_this_process(*request, collect.output);
  return encode(collect.output);
}

// The speaker initialises the engine once, before its first child.
void prepare() { started(); }

constexpr SpeakerWork kSpeakerWork{prepare, serve};

// How a child that did not finish ended, for an error: "crashed (signal 11)".
std::string failure(const ForkedOutcome& forked) {
  switch (forked.end) {
    case ForkedOutcome::End::failed:
      return forked.detail > 0 ? "crashed (signal " + std::to_string(forked.detail) + ")"
                               : "stopped (exit status " + std::to_string(-forked.detail) + ")";
    case ForkedOutcome::End::too_large:
      return "answered more than was asked for";
    case ForkedOutcome::End::could_not_start:
      return forked.detail == ESRCH ? std::string("process has ended")
                                    : std::string("could not start a process (") + std::strerror(forked.detail) + ")";
    case ForkedOutcome::End::finished:
      break;
  }
  return "failed";
}

Result<Utterance> speak(const SpeechRequest& request) {
  const std::lock_guard lock(engine_mutex());
  const Engine& engine = started();
  if (engine.sample_rate == 0)
    return make_error(codes::speech::engine_missing, request.where,
                      "the speech engine (eSpeak NG) could not start: is espeak-ng-data installed?");
  if (!plain_name(request.language))
    return make_error(codes::speech::bad_language, request.where,
                      "'" + request.language + "' is not a language name (like en, en-us, fr, de)");
  if (!request.voice.empty() && (!plain_name(request.voice) ||
                                 !std::filesystem::is_regular_file(engine.data / "voices" / "!v" / request.voice))) {
    return make_error(codes::speech::unknown_voice, request.where,
                      "unknown voice '" + request.voice +
                          "' (voice variants of eSpeak NG: m1..m7, f1..f5, klatt, whisper, ...; `espeak-ng "
                          "--voices=variant` lists them)");
  }
  const std::string language = lower(request.language);
  if (engine.mbrola.count(language) != 0 || language.rfind("mb-", 0) == 0)
    return make_error(codes::speech::mbrola_voice, request.where,
                      "'" + request.language +
                          "' is an MBROLA voice: fapc speaks only with eSpeak NG's own voices "
                          "(an MBROLA voice runs an outside program; `espeak-ng --voices` lists the others)");
  if (engine.own.count(language) == 0)
    return make_error(codes::speech::unknown_language, request.where,
                      "unknown language '" + request.language + "' (`espeak-ng --voices` lists the languages)");
  const int rate = static_cast<int>(request.words_per_minute + 0.5);
  if (rate < espeakRATE_MINIMUM || rate > espeakRATE_MAXIMUM)
    return make_error(codes::speech::rate_out_of_range, request.where,
                      "the speech rate " + std::to_string(rate) + " words per minute is outside 80 to 450");

  const auto max_samples = static_cast<std::size_t>(std::max(0.0, request.max_seconds) * engine.sample_rate);
  // Started here when nobody started it earlier (start_engine_process): this process may run
  // other threads by now, a risk taken once, never again for its utterances.
  if (start_speaker(kSpeakerWork, true) != SpeakerStart::started)
    return make_error(
        codes::speech::engine_failed, request.where,
        std::string("the speech engine (eSpeak NG) could not start a process (") + std::strerror(errno) + ")");
  const ForkedOutcome forked =
      ask_speaker(kSpeakerWork, encode(EngineRequest{request.language, request.voice, rate, max_samples, request.text}),
                  // The samples, and a generous bound on the events (a few per character of text).
                  max_samples * sizeof(std::int16_t) + 64 * request.text.size() + 4096, kMaxEngineMessageBytes);
  if (forked.end != ForkedOutcome::End::finished)
    return make_error(codes::speech::engine_failed, request.where,
                      "the speech engine (eSpeak NG) " + failure(forked) + " on this text");
  std::optional<EngineOutput> collected = decode_engine_output(forked.output);
  if (!collected)
    return make_error(codes::speech::engine_failed, request.where,
                      "the speech engine (eSpeak NG) sent back a malformed result");
  switch (collected->stop) {
    case EngineOutput::Stop::spoken:
      break;
    case EngineOutput::Stop::language_refused:
      return make_error(codes::speech::unknown_language, request.where,
                        "unknown language '" + request.language + "' (`espeak-ng --voices` lists the languages)");
    case EngineOutput::Stop::voice_refused:
      return make_error(codes::speech::unknown_voice, request.where,
                        "eSpeak NG refused the voice '" + request.language + "+" + request.voice + "'");
    case EngineOutput::Stop::too_long:
      return make_error(codes::limit::speech_seconds, request.where,
                        "the speech would last more than " + std::to_string(request.max_seconds) + " s");
    case EngineOutput::Stop::synth_failed:
      return make_error(
          codes::speech::engine_failed, request.where,
          "eSpeak NG failed to synthesise this text (error " + std::to_string(collected->synth_status) + ")");
  }
  EngineOutput& spoken = *collected;

  Utterance out;
  out.warnings = engine_message_warnings(forked.messages, forked.messages_dropped, request.where);
  out.audio.sample_rate = engine.sample_rate;
  out.audio.samples = std::move(spoken.samples);
  out.audio.source = request.where;
  out.duration = static_cast<double>(out.audio.samples.size()) / engine.sample_rate;
  std::set<std::string> unknown;
  const auto& phonemes = spoken.phonemes;
  for (std::size_t i = 0; i < phonemes.size(); ++i) {
    const auto& [name, ms] = phonemes[i];
    if (name.empty() || name[0] == '(') continue;  // a language switch mark, not a sound
    SpokenPhoneme p;
    p.name = name;
    p.begin = std::min(out.duration, ms / 1000.0);
    p.end = i + 1 < phonemes.size() ? std::min(out.duration, phonemes[i + 1].second / 1000.0) : out.duration;
    p.viseme = viseme_of_espeak_phoneme(request.language, name);
    if (p.viseme < 0) {
      if (unknown.insert(name).second)
        out.warnings.push_back(
            make_warning(request.where, "the speech engine's phoneme '" + name + "' (" + request.language +
                                            ") has no viseme in fapc's table: the mouth keeps the shape around it"));
      p.viseme = 0;
    }
    out.phonemes.push_back(std::move(p));
  }
  // eSpeak NG counts characters (UTF-8 sequences) from 1; callers want byte offsets.
  std::size_t byte = 0;
  int character = 1;
  for (const auto& [position, ms] : spoken.words) {
    while (character < position && byte < request.text.size()) {
      ++byte;
      while (byte < request.text.size() && (static_cast<unsigned char>(request.text[byte]) & 0xC0) == 0x80) ++byte;
      ++character;
    }
    out.words.push_back({byte, std::min(out.duration, ms / 1000.0)});
  }
  return out;
}

}  // namespace

bool available() { return true; }

std::string engine_name() {
  const char* path = nullptr;
  const char* version = espeak_Info(&path);
  return std::string("eSpeak NG ") + (version != nullptr ? version : "");
}

Synthesizer engine() { return speak; }

bool start_engine_process() { return start_speaker(kSpeakerWork, false) == SpeakerStart::started; }

}  // namespace fapc::speech

#else

namespace fapc::speech {

bool available() { return false; }
std::string engine_name() { return "none"; }
Synthesizer engine() { return {}; }
bool start_engine_process() { return false; }

}  // namespace fapc::speech

#endif

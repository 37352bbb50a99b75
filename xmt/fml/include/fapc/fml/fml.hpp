// The FML reader (docs/fml.md): an Arya-DiPaola Face Modeling Language document
// lowered to the shared timeline through fapc::schedule(). Moves ramp their target from its
// current value to theirs and hold it; talk becomes FAP 1 visemes, expr FAP 2 expressions, hdmv
// the head rotation FAPs; excl branches are chosen by event values given up front.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/profile.hpp"
#include "fapc/transcoder/speech.hpp"
#include "fapc/transcoder/timeline.hpp"

namespace fapc::xmt {

struct FmlOptions {
  // Event values (--event NAME=VALUE); they win over the model's <event val>.
  std::map<std::string, std::string> events;
  // The story's end when the document gives none (--duration): lets indefinite repeats end.
  std::optional<double> duration;
  // The most runs (elements after template expansion, runs after repeats): Limits::max_runs.
  std::int64_t max_runs = Limits{}.max_runs;
  // The frames the story will be rendered at: a story too long for them is refused once it is
  // scheduled, before its clips are made (the error FrameStream::start would give). fps 0: unchecked.
  FrameBudget frames;
  // Names that `param` moves may use besides the FAP names; nullptr: the default profile.
  const Profile* profile = nullptr;
  // talk text (docs/speech.md): spoken by `synthesize` (fapc::speech::engine()); without one, the
  // letter-to-viseme approximation at words_per_minute * 12 / 175 visemes per second, with a
  // warning. The language and voice variant apply where neither the talk nor the model's
  // character names one.
  Synthesizer synthesize;
  std::string language = "en";
  std::string voice;
  double words_per_minute = 175;
  double max_speech_seconds = 3600;  // per talk (the frame limit at the frame rate): longer is refused
  // The document's talk text and speech, all talks together (Limits::max_speech_text_bytes and
  // max_speech_seconds, docs/security.md): checked before each talk is spoken, the seconds first
  // as estimated from the text (estimated_speech_seconds), then as spoken.
  Limits speech_limits;
  Coarticulation coarticulation;
  // Reads the phoneme file of `talk file=` (a path already resolved against the document's
  // folder); empty: read from disk.
  std::function<Result<std::string>(const std::string& path)> read_file;
  // Which files `talk file=` may name (docs/security.md); by default the document's folder tree.
  IncludePolicy includes;
};

struct FmlDocument {
  Timeline timeline;                                        // explicit_end: the story's end
  std::string character;                                    // model <character name>
  std::vector<std::pair<std::string, std::string>> events;  // name, the value used ("" when none)
  std::vector<std::string> templates;                       // model template names
  std::vector<std::string> phoneme_files;                   // resolved paths of talk file=
  std::vector<std::string> languages;                       // the languages talk text was spoken in
  Diagnostics warnings;
};

// Errors (file:line:col): not well-formed XML, another format than FML (named: Greta FML-APML,
// APML, BML, Xface SMIL-Agent, XMT), malformed timing or values, unknown templates, recursion.
Result<FmlDocument> read_fml(std::string_view text, const std::string& file_name, const FmlOptions& options = {});
Result<FmlDocument> load_fml(const std::string& path, const FmlOptions& options = {});

}  // namespace fapc::xmt

// The reader's limits (docs/security.md): elements and runs against --max-runs, the speech budget,
// the voice placed by every run; and the scheduler's errors, named by their element.
#include <algorithm>
#include <cstdio>

#include "fapc/transcoder/audio_mix.hpp"
#include "fml/fml_reader.hpp"

namespace fapc::fml::reading {

bool FmlReader::count_node(const xmlNode* node) {
  if (++nodes_ <= static_cast<double>(options_.limits.max_runs)) return true;
  fail(limit_at(doc_.error(codes::limit::runs, node, ""), "the story has too many elements after template expansion"));
  return false;
}

// Every run of a spoken talk stores its own copy of the voice: their sum against the audio
// sample limit, before any is made (a talk repeated 10^5 times).
Status FmlReader::check_placed_voice(const Schedule& schedule) const {
  double samples = 0;
  for (const Occurrence& run : schedule.occurrences) {
    const FmlLeaf& leaf = tree_.leaves[run.leaf_id];
    if (leaf.kind != FmlLeaf::Kind::talk || run.end <= run.begin) continue;
    samples += placed_samples(leaf.talk->audio, run.begin - run.curve_offset, run.begin, run.end);
    if (samples > static_cast<double>(options_.limits.max_audio_samples))
      return placed(limit_error(leaf.where,
                                "the voice of this talk, once per run, adds up to " +
                                    std::to_string(static_cast<std::int64_t>(samples)) + " samples",
                                Limit::audio_samples, options_.limits));
  }
  return ok_status();
}

Diagnostic FmlReader::placed(Diagnostic d) const {
  d.source_line = doc_.line_text(d.where.line);
  return d;
}

std::string FmlReader::seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", seconds);
  return text;
}

// Runs the tree would make, against max_runs, before the scheduler makes them (estimated_runs,
// fml_timing.hpp): a talk makes a run per viseme, a "normal" one per expression placed.
double FmlReader::leaf_runs(std::size_t leaf_id) const {
  const FmlLeaf& leaf = tree_.leaves[leaf_id];
  return leaf.kind == FmlLeaf::Kind::talk ? std::max<double>(1, static_cast<double>(leaf.talk->speech.visemes.size()))
         : leaf.kind == FmlLeaf::Kind::normal ? std::max<double>(1, static_cast<double>(expressions_.size()))
                                              : 1;
}

Status FmlReader::check_runs() const {
  double shortest = 0;
  const double total = estimated_runs(tree_.root, options_.duration.value_or(kUnendedSeconds), shortest,
                                      [this](std::size_t leaf_id) { return leaf_runs(leaf_id); });
  if (total <= static_cast<double>(options_.limits.max_runs)) return ok_status();
  return limit_at(make_error(codes::limit::runs, tree_.root.source, ""), "the story repeats to too many runs");
}

// A limit_exceeded error at the place `at` points to (its source line kept).
Diagnostic FmlReader::limit_at(const Diagnostic& at, const std::string& what) const {
  Limits limits;
  limits.max_runs = options_.limits.max_runs;
  Diagnostic d = limit_error(at.where, what, Limit::runs, limits);
  d.source_line = at.source_line;
  return d;
}

// The scheduler's problem, its subject the element it is about.
Diagnostic FmlReader::scheduler_error(const ScheduleError& problem) const {
  const bool named = problem.node_tag > 0 && problem.node_tag <= element_names_.size();
  Diagnostic d =
      problem.diagnostic(named ? names_.name(element_names_[problem.node_tag - 1]) : std::string("the element"));
  if (named && problem.needs_an_end()) {
    d.message +=
        " (repeat=\"indefinite\" and unset loop events need an end: a container's duration or end, "
        "or --duration)";
  }
  if (d.where.file == doc_.file() && d.source_line.empty()) d.source_line = doc_.line_text(d.where.line);
  return d;
}

// The document's talk text against the speech budget before it is parsed, so that no talk is
// spoken when the talks together pass it (a read streamed story is otherwise spoken talk by talk
// as it is read: 10^4 short talks took 12 s before the last ones were refused). A lexical scan
// of <talk ...>TEXT</talk> without file=, in document order: an estimate (it counts markup
// inside a talk, and talks in comments), made exact by the checks as each talk is spoken.
std::optional<Diagnostic> talk_text_over_budget(std::string_view text, const std::string& file,
                                                const ReaderOptions& options) {
  const Limits& limits = options.limits;
  std::int64_t bytes = 0;
  double seconds = 0;
  for (std::size_t at = text.find("<talk"); at != std::string_view::npos; at = text.find("<talk", at + 1)) {
    const char after = at + 5 < text.size() ? text[at + 5] : '\0';
    if (after != '>' && after != ' ' && after != '\t' && after != '\n' && after != '\r') continue;
    const std::size_t open_end = text.find('>', at);
    if (open_end == std::string_view::npos) break;
    if (text[open_end - 1] == '/' || text.substr(at, open_end - at).find("file") != std::string_view::npos) continue;
    const std::size_t close = text.find("</talk", open_end);
    if (close == std::string_view::npos) break;
    const std::string_view body = text.substr(open_end + 1, close - open_end - 1);
    bytes += static_cast<std::int64_t>(body.size());
    seconds += estimated_speech_seconds(body, options.speech.words_per_minute);
    const bool too_much_text = bytes > limits.max_speech_text_bytes;
    if (too_much_text || seconds > limits.max_speech_seconds) {
      const std::size_t line_start = text.rfind('\n', at);
      const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
      const Location where =
          Location::text(file, static_cast<int>(line),
                         static_cast<int>(at - (line_start == std::string_view::npos ? 0 : line_start + 1)) + 1);
      char shown[32];
      std::snprintf(shown, sizeof shown, "%.0f", seconds);
      return too_much_text
                 ? limit_error(where, "the talk text of this document reaches " + std::to_string(bytes) + " bytes",
                               Limit::speech_text, limits)
                 : limit_error(where, std::string("the speech of this document would last at least ") + shown + " s",
                               Limit::speech_seconds, limits);
    }
    at = close;
  }
  return std::nullopt;
}

}  // namespace fapc::fml::reading

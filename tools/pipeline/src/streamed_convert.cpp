// The one engine's streamed road (docs/architecture.md, "One engine"): an input's frames taken one
// at a time from its source (a mapped .fap, a decoded .fba, a script's timeline rendered frame by
// frame) to writers that take them so (.fba, .mp4, .fap), without the frames in memory:
//
//   pass 1: source (read, decoded or rendered)  --frames-->  FrameWriter::check, FrameTape
//   pass 2: FrameTape (or the source again), frames numbered as placed in time
//                                               --frames-->  FrameWriter::add
//
// One pass when no writer checks first and the writers can write before the facts: a script knows
// its length up front, and a .fap body can wait in a scratch file for its header. Each output goes
// to a temporary file renamed over it at commit, in request order, up to the first that fails.
// What comes out (bytes, warnings, errors) is what loading and writing gives, byte for byte.
#include "streamed_convert.hpp"

#include <algorithm>
#include <memory>

#include "fap_text_outputs.hpp"
#include "fapc/codec/file_io.hpp"
#include "frame_source.hpp"

namespace fapc::pipeline {

namespace {

bool is_gzip_path(const std::string& path) { return path.size() >= 3 && path.compare(path.size() - 3, 3, ".gz") == 0; }

// Whether the reader and every writer can take the frames one at a time.
bool can_stream(const InputFormat* reader, const std::string& input, const std::vector<OutputRequest>& outputs,
                const std::vector<const OutputFormat*>& writers, const ConvertOptions& options) {
  if (input == "-" || !reader || options.facts || outputs.empty()) return false;
  if (!reader->timeline && !reader->frames) return false;
  // A script's encoding is verified the loaded way (the tape serves frame files).
  if (reader->timeline && options.verify) return false;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (!writers[i]->frame_writer || outputs[i].path == "-" || is_gzip_path(outputs[i].path)) return false;
    // A script's voice is known once it is lowered, and only the loaded writers carry one.
    if (reader->timeline && writers[i]->uses_audio) return false;
  }
  return true;
}

// The source of `input`'s frames; null when the usual way must read it (an unreadable, empty or
// gzip file: the usual way reports, reads or inflates it).
Result<std::unique_ptr<FrameSource>> open_source(const InputFormat& reader, const std::string& input,
                                                 const ConvertOptions& options) {
  if (reader.timeline) return open_timeline_source(input, options);
  auto mapped = MappedFile::open(input);
  if (!mapped || mapped->bytes().empty() || is_gzip(mapped->bytes())) return std::unique_ptr<FrameSource>();
  return reader.frames(std::move(*mapped), input, options);
}

// The result's facts of the first pass, as loading would give them; false (and the error set)
// when the pass failed or --strict refuses the warnings.
bool take_facts(ConvertResult& result, const Result<SourceFacts>& read, const std::bitset<kFapCount>& faps,
                const std::string& input, const ConvertOptions& options) {
  if (!read) {
    result.error = read.error();
    return false;
  }
  const SourceFacts& facts = *read;
  result.warnings = facts.warnings;
  result.loaded.origin = input;
  result.loaded.frames.name = facts.name;
  result.loaded.frames.fps = facts.fps;
  result.loaded.warnings = facts.warnings;
  result.frames = {facts.frames, facts.fps, faps};
  if (!facts.numbered_from_zero) result.frames.last_number = facts.last_number;
  if (options.strict && !result.warnings.empty()) {
    result.error = strict_error(input, result.warnings.size());
    return false;
  }
  return true;
}

}  // namespace

std::optional<ConvertResult> convert_streamed(const std::string& input, const std::vector<OutputRequest>& outputs,
                                              const std::vector<const OutputFormat*>& writers,
                                              const ConvertOptions& options) {
  const InputFormat* reader = reader_for(input, options);
  if (!can_stream(reader, input, outputs, writers, options)) return std::nullopt;
  const auto steps = static_cast<std::int64_t>(outputs.size()) + 1;
  if (options.progress) options.progress("reading " + input, 0, steps);
  ConvertResult result;
  auto opened = open_source(*reader, input, options);
  if (!opened) {
    result.error = opened.error();
    return result;
  }
  if (!*opened) return std::nullopt;
  FrameSource& source = **opened;
  std::vector<std::unique_ptr<FrameWriter>> sinks;
  std::vector<FrameWriter*> checkers;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    sinks.push_back(writers[i]->frame_writer(outputs[i].path, input, options, source));
    if (sinks.back()->checks_first()) checkers.push_back(sinks.back().get());
  }

  // One pass when no writer must see every frame first, and every writer either gets the facts
  // before the frames or can write without them.
  const std::optional<SourceFacts> up_front = source.facts_up_front();
  const bool one_pass =
      checkers.empty() &&
      (up_front || std::all_of(sinks.begin(), sinks.end(), [](const auto& w) { return w->writes_before_facts(); }));
  for (const auto& w : sinks) {
    if (!one_pass) break;
    if (up_front)
      w->start(*up_front);
    else
      w->start_early();
  }
  // Pass 1. The frames go on the tape where a second pass follows and that pays: for an encoder
  // (as fast as reading a .fap again, and a lower peak: 149 against 165 MB at 10^6 frames) and from
  // a source that decodes or renders (replaying takes a third of the time of decoding again). A
  // .fap only rewritten as .fap is read again (the tape would be some 50 bytes a frame more).
  const bool onto_tape = !one_pass && (!checkers.empty() || source.placed_in_first_pass());
  std::bitset<kFapCount> faps;
  auto facts = source.first_pass(
      [&](const FapFrame& frame) -> Status {
        faps |= frame.mask;
        for (FrameWriter* w : checkers) w->check(frame);
        if (one_pass)
          for (const auto& w : sinks) w->add(frame);
        return ok_status();
      },
      onto_tape);
  if (!take_facts(result, facts, faps, input, options)) return result;
  // --verify compares the streams with the frames on the tape; frames too many for it take the
  // usual way (nothing is written yet).
  if (options.verify && !checkers.empty() && !source.taped()) return std::nullopt;

  // Pass 2: the frames again, numbered as placed in time.
  if (!one_pass || !up_front)
    for (const auto& w : sinks) w->start(*facts);
  if (!one_pass && std::any_of(sinks.begin(), sinks.end(), [](const auto& w) { return w->wants_frames(); })) {
    auto again = source.second_pass(
        [&](const FapFrame& frame) -> Status {
          for (const auto& w : sinks) w->add(frame);
          return ok_status();
        },
        options.verify);
    if (!again) {
      result.error = again.error();
      return result;
    }
  }
  for (const auto& w : sinks) w->finish();

  // The outputs in request order, up to the first that failed (as the usual way writes them).
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (options.progress) options.progress("writing " + outputs[i].path, static_cast<std::int64_t>(i) + 1, steps);
    if (auto written = sinks[i]->commit(); !written) {
      result.error = written.error();
      return result;
    }
    result.written.push_back(outputs[i].path);
  }
  if (options.progress) options.progress("done", steps, steps);
  return result;
}

}  // namespace fapc::pipeline

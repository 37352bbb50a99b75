// What every script reader is told (Mimic, FML, XMT-Omega, BML, SMIL-Agent, FML-APML, APML): one
// value, built once by the pipeline from its ConvertOptions and handed to every reader. A reader
// reads the fields it has a use for and leaves the rest; what only one reader needs (XMT-Omega's
// loader of `animation src`, the intentions' lexicon) is in that reader's own options beside it.
// A new option is declared in the program's table (tools/fapc/cli_spec.cpp), becomes a field of
// ConvertOptions and of this value, and is read by the reader it is for (docs/architecture.md).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/profile.hpp"
#include "fapc/transcoder/speech.hpp"

namespace fapc {

// How text is spoken (docs/speech.md): by `synthesize` (fapc::speech::engine()), or without one
// by the FML reader's letter-to-viseme approximation at words_per_minute * 12 / 175 visemes a
// second, with a warning. The language and voice variant apply where the document names none.
struct SpeechOptions {
  Synthesizer synthesize;
  std::string language = "en";
  std::string voice;
  double words_per_minute = 175;
  // One speech (a talk, a speech element) longer than this is refused: the frame limit at the
  // frame rate. All of a document's speech together is bounded by Limits::max_speech_seconds.
  double max_seconds = 3600;
  Coarticulation coarticulation;
};

// A document another reader takes, known by its root element: a reader handed one by mistake
// names the reader to use ("a bml document: fapc reads it as .bml, not FML"). The pipeline makes
// the list from its table's rows (their xml_roots), so that no reader lists other formats.
struct OtherReader {
  std::string root;       // lower case, as the row lists it
  std::string kind;       // the row's kind name
  std::string extension;  // the row's first extension
};

struct ReaderOptions {
  // The resource limits of the read (docs/security.md): max_runs bounds the elements, behaviours
  // and runs after repeats (--max-runs); the speech text and seconds of the whole document, the
  // bytes of a file an element reads (a WAV, a .pho: max_decompressed_bytes) and its samples.
  Limits limits;
  // The frames the script will be rendered at: a script too long for them is refused once it is
  // scheduled, before its clips are made (the error FrameStream::start would give). fps 0:
  // unchecked (an included document, whose frames are never made).
  FrameBudget frames;
  // Which files the script may name (defxpr, talk file=, animation src, audio, speech file=:
  // docs/security.md); by default the script's own folder tree.
  IncludePolicy includes;
  // Reads a file the script names (a path already resolved and allowed); empty: read from disk.
  // Tests and fuzzers pass their own.
  std::function<Result<std::string>(const std::string& path)> read_file;
  // Names that parameters may use besides the FAP names; nullptr: default_profile().
  const Profile* profile = nullptr;
  // Event values (--event NAME=VALUE); they win over the document's own.
  std::map<std::string, std::string> events;
  // The end when the document gives none (--duration): lets indefinite repeats end.
  std::optional<double> duration;
  SpeechOptions speech;
  // The other readers' roots (OtherReader); empty: a reader names none.
  std::vector<OtherReader> other_readers;
};

}  // namespace fapc

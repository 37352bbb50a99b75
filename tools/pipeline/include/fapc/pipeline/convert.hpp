// Convert: load one input, write it as one or more outputs, atomically. Nothing is printed: the
// result carries every warning and the error, for the caller to show.
#pragma once

#include <bitset>
#include <optional>
#include <string>
#include <vector>

#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline {

struct OutputRequest {
  std::string path;  // "-": the bytes are returned in ConvertResult::standard_output
  std::string kind;  // empty: from the path's extension
};

struct ConvertResult {
  Loaded loaded;                     // what the input became (frames empty when the load failed)
  Diagnostics warnings;              // in the order met
  std::optional<Diagnostic> error;   // the first error; outputs after it were not written
  std::vector<std::string> written;  // the files written, in request order
  std::string standard_output;       // the bytes of a "-" output
  // What the frames were, for summaries, also when they went through without being held (a long
  // .fap streamed to .fba and .fap, a script compiled to curve outputs only: loaded.frames has none).
  using FramesSeen = pipeline::FramesSeen;
  FramesSeen frames;
  bool ok() const { return !error; }
};

// What `loaded`'s frames were, whether it holds them or not (Loaded::frames_not_kept).
FramesSeen frames_seen(const Loaded& loaded);

// The writer for a request, or an error (unsupported) naming the known output kinds.
Result<const OutputFormat*> writer_for(const OutputRequest& request);

// The bytes of `loaded` as the requested output.
Result<std::string> render_output(const Loaded& loaded, const OutputRequest& request, const ConvertOptions& options);

// Writes `loaded` to each output in turn (atomically: a failed output leaves no file), stopping at
// the first error. Every writer is found before anything is written.
ConvertResult write_outputs(Loaded loaded, const std::vector<OutputRequest>& outputs, const ConvertOptions& options);

// Loads `input` once and writes every output. Under options.strict a warning is an error and
// nothing is written.
ConvertResult convert(const std::string& input, const std::vector<OutputRequest>& outputs,
                      const ConvertOptions& options);

}  // namespace fapc::pipeline

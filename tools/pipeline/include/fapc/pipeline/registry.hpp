// The readers and writers, in two tables (the model: pandoc's reader and writer tables). A
// format is one entry: its kind name, its extensions and one function. The built-in tables are
// assembled by one function from the list in src/registry.cpp, not by static initialisers, which
// a static link may drop.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "fapc/pipeline/loaded.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::pipeline {

struct InputFormat {
  std::string kind;                     // "fap", "fba", "mimic", ...
  std::vector<std::string> extensions;  // ".fap", ".fap.gz"
  std::function<Result<Loaded>(const std::string& path, const ConvertOptions&)> load;
  std::string carries{};                // what a file of this kind holds, for `fapc formats`
  std::vector<std::string> options{};   // the command-line options that change how it is read
};

struct OutputFormat {
  std::string kind;
  std::vector<std::string> extensions;  // the first one names batch outputs
  // The bytes to write for `path` (the name may go into the output, e.g. an .xmt's stream source).
  std::function<Result<std::string>(const Loaded&, const std::string& path, const ConvertOptions&)> write;
  // The writer reads Loaded::curves (a script's own curves): convert() has them computed only
  // when some output does (ConvertOptions::curves).
  bool uses_curves = false;
  // The writer reads Loaded::frames even when the input is a timeline. When no output does,
  // convert() renders a script's frames without keeping them (ConvertOptions::frames). Writers
  // of curves read the frames only of inputs without a timeline, which always have them.
  bool uses_frames = true;
  std::string carries{};               // what a file of this kind holds, for `fapc formats`
  std::vector<std::string> options{};  // the command-line options that change what is written
  // What this output cannot carry of the frames, as warnings (docs/bridges.md); computed for every
  // output before any is written, so that --strict refuses before writing. Empty: nothing lost.
  std::function<Diagnostics(const Loaded&, const std::string& path)> losses{};
};

class Registry {
 public:
  void add(InputFormat format) { inputs_.push_back(std::move(format)); }
  void add(OutputFormat format) { outputs_.push_back(std::move(format)); }

  // By the longest matching extension (".fap.gz" before ".gz"), or by kind name; null if none.
  const InputFormat* input_for(const std::string& path) const;
  const OutputFormat* output_for(const std::string& path) const;
  const InputFormat* input_named(const std::string& kind) const;
  const OutputFormat* output_named(const std::string& kind) const;

  const std::vector<InputFormat>& inputs() const { return inputs_; }
  const std::vector<OutputFormat>& outputs() const { return outputs_; }

 private:
  std::vector<InputFormat> inputs_;
  std::vector<OutputFormat> outputs_;
};

// Every built-in reader and writer. Built on first use; safe to share between threads.
const Registry& formats();

// The reader of a top input: options.input_kind's when given, else the one its extension names;
// null if none.
const InputFormat* reader_for(const std::string& path, const ConvertOptions& options);

// "unknown input kind 'fbx'; did you mean fba?" or, by extension, the kinds expected.
Diagnostic unknown_input_kind(const std::string& path, const ConvertOptions& options);

// Loads any input the built-in readers know (by --from or extension), or says why not (unsupported for an
// unknown extension). Includes and operands inside inputs are loaded through this too.
Result<Loaded> load(const std::string& path, const ConvertOptions& options);

}  // namespace fapc::pipeline

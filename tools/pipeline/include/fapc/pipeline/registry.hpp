// The readers and writers, in two tables (the model: pandoc's reader and writer tables). A
// format is one entry: its kind name, its extensions, one function, and what else the pipeline may
// do with it (its capabilities: fields with defaults, so that an entry of a kind name, extensions
// and a function is a whole reader or writer). The row is the only place that knows a format:
// nothing outside the entries compares kind names or extensions (tests/pipeline/
// one_place_per_format_test.cpp). The built-in tables are assembled by one function from the list
// in src/registry.cpp, not by static initialisers, which a static link may drop.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/loaded.hpp"
#include "fapc/pipeline/options.hpp"
#include "fapc/pipeline/verify.hpp"

namespace fapc::pipeline {

// The one engine's pieces (src/frame_source.hpp, private to the pipeline): frames read one at a
// time, and a writer that takes them so.
class FrameSource;
class FrameWriter;

struct InputFormat {
  std::string kind;                     // "fap", "fba", "mimic", ...
  std::vector<std::string> extensions;  // ".fap", ".fap.gz"
  std::function<Result<Loaded>(const std::string& path, const ConvertOptions&)> load;
  std::string carries{};               // what a file of this kind holds, for `fapc formats`
  std::vector<std::string> options{};  // the command-line options that change how it is read

  // Capabilities: what the one engine (convert, docs/architecture.md) may do besides loading.
  // A script: lowered to a timeline (ConvertOptions::render false), then rendered frame by frame.
  bool timeline = false;
  // Frames read one at a time from the mapped file (gzip and empty files are loaded whole); null
  // for a reader that only loads.
  std::function<std::unique_ptr<FrameSource>(MappedFile file, const std::string& path, const ConvertOptions&)> frames{};
  // An FBA stream, bare or in a container: `fapc decode` reads it, and `verify` checks with this
  // that it re-encodes to the same bytes; null for every other input (encoded, then checked).
  std::function<VerifyResult(const std::string& path, const Limits&)> verify_stream{};
  // The root elements (lower case) of the XML documents this reader takes when they are named .xml
  // (docs/bml.md, "Inputs named .xml"): the .xml row hands a document to the row naming its root.
  std::vector<std::string> xml_roots{};
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

  // Capabilities (docs/architecture.md, "One engine"):
  // The writer reads Loaded::audio, the voice. A script's voice is known only once it is lowered,
  // so such an output takes a script the loaded way.
  bool uses_audio = false;
  // It draws the face (what `fapc render` writes).
  bool picture = false;
  // It takes the frames one at a time: the writer of output `path` made from `input` whose frames
  // come from `source`. With every requested writer so, convert() streams; null: it needs them all.
  std::function<std::unique_ptr<FrameWriter>(const std::string& path, const std::string& input, const ConvertOptions&,
                                             FrameSource& source)>
      frame_writer{};
  // What this output cannot carry of the frames, as warnings (docs/bridges.md); computed for every
  // output before any is written, so that --strict refuses before writing. Empty: nothing lost.
  std::function<Diagnostics(const Loaded&, const std::string& path)> losses{};
  // What this output refuses of an animation from its length alone (`frames` on a grid of `fps`):
  // asked before a script's frames are rendered, so that a video too long for its limits is
  // refused up front (docs/security.md, "Resource limits"). `ends` is the place that ends the
  // animation, where length errors point. Empty: the output takes any length the frames may have.
  std::function<Status(std::int64_t frames, int fps, const Location& ends, const std::string& path,
                       const ConvertOptions&)>
      check_length{};
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
  // The reader of .xml documents whose root element is `root` (lower case); null if none.
  const InputFormat* input_for_xml_root(const std::string& root) const;

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
// The same for outputs: `kind` (empty: by the extension of `path`) names no writer.
Diagnostic unknown_output_kind(const std::string& path, const std::string& kind);
// The message alone, for a kind given by name: "unknown input kind 'fbx'; did you mean fba? (fapc
// formats lists them)". `outputs` picks the table. Used by every command and by batch.
std::string unknown_kind_message(const std::string& kind, bool outputs);

// The tables' kinds and extensions as a list for people: "fap, fba or mp4", ".fap, .fba or .mp4".
// `which` picks the rows (every row when empty).
std::string kind_list(const std::vector<const InputFormat*>& rows);
std::string kind_list(const std::vector<const OutputFormat*>& rows);
std::string extension_list(const std::vector<const InputFormat*>& rows);
std::string extension_list(const std::vector<const OutputFormat*>& rows);
// Every row of a table, or those with a capability.
std::vector<const InputFormat*> inputs_where(const std::function<bool(const InputFormat&)>& keep = {});
std::vector<const OutputFormat*> outputs_where(const std::function<bool(const OutputFormat&)>& keep = {});

// The warnings (format.option_not_read) for options.given that change how some kind is read but
// that neither the row of `input`'s reader nor any of `writers` names: given, they change nothing.
Diagnostics options_not_read(const std::string& input, const std::vector<const OutputFormat*>& writers,
                             const ConvertOptions& options);

// Loads any input the built-in readers know (by --from or extension), or says why not (unsupported for an
// unknown extension). Includes and operands inside inputs are loaded through this too.
Result<Loaded> load(const std::string& path, const ConvertOptions& options);

}  // namespace fapc::pipeline

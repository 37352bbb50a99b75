// The registries of the fapc program: subcommands, input formats and output formats. Each lives in
// its own .cpp file and registers itself with a static Register* object, so the command table and
// the format table are assembled at start-up and no central list needs editing.
#pragma once

#include <functional>
#include <map>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/transcoder/curves.hpp"
#include "fapc/transcoder/timeline.hpp"

namespace fapc::cli {

// docs/cli.md: exit statuses.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitVerifyFailed = 3;

// ---- subcommands -------------------------------------------------------------------------------

using CommandFn = int (*)(const std::vector<std::string>& args);

struct Command {
  std::string name;
  std::string usage;  // one line, as in docs/cli.md
  CommandFn run;
};

struct RegisterCommand {
  RegisterCommand(std::string name, std::string usage, CommandFn run);
};

const std::map<std::string, Command>& commands();

// ---- conversion options shared by compile, batch and the format handlers ---------------------

// The picture outputs (.png, .webm, .html): --size, --frame-rate, --frame, --time, --sheet.
struct PictureSettings {
  int width = 640;
  int height = 480;
  int frame_rate = 0;                 // 0: the input's own frame rate
  std::optional<std::int64_t> frame;  // .png: this frame of the input's grid
  std::optional<double> time;         // .png: the frame at this time
  std::optional<int> sheet;           // .png: a contact sheet of N frames
  bool points = false;                // .png: the feature points marked and numbered
};

struct ConvertOptions {
  int fps = 25;
  PictureSettings picture;
  std::optional<std::string> profile;
  std::optional<double> duration;             // --duration: the end of timelines that give none
  std::map<std::string, std::string> events;  // --event NAME=VALUE
  double visemes_per_second = 12;             // --speech-rate: FML talk text
  int quant = 1;                             // fap_quant for .fba/.mp4 outputs
  int intra_period = 0;                      // 0: encoder decides
  std::string ranges = "fit";                // fit | max
  std::string masks = "fit";                 // fit | keep
  FapFlavour fap_flavour = FapFlavour::safe;  // --fap-flavour: the .fap layout of a player family
  bool strict = false;
  bool verify = false;
  // Which files includes may read (docs/security.md): the --allow-include folders; load_input
  // adds the top input's folder.
  IncludePolicy includes;
};

// What an input became: always frames; the timeline and its curves when the front end has them
// (Mimic, FML, XMT-Omega), so curve outputs and per-clip plots keep the authored shape.
struct Loaded {
  FapSequence frames;
  std::optional<Curves> curves;
  std::optional<Timeline> timeline;
  Diagnostics warnings;
};

struct InputFormat {
  std::string kind;                     // "fap", "fba", "mimic", ...
  std::vector<std::string> extensions;  // ".fap", ".fap.gz"
  std::function<Result<Loaded>(const std::string& path, const ConvertOptions&)> load;
  // Optional: facts for `fapc info` beyond the generic frame summary (format variant, stream
  // statistics, tracks...). Keys become lines of the text output and members of --json.
  std::function<Result<nlohmann::ordered_json>(const std::string& path, const ConvertOptions&)>
      describe;
};

struct OutputFormat {
  std::string kind;
  std::vector<std::string> extensions;
  // The bytes to write for `path` (the name may go into the output, e.g. a .fap header).
  std::function<Result<std::string>(const Loaded&, const std::string& path, const ConvertOptions&)>
      write;
};

struct RegisterInput {
  explicit RegisterInput(InputFormat format);
};
struct RegisterOutput {
  explicit RegisterOutput(OutputFormat format);
};

// Lookup by the longest matching extension (".fap.gz" before ".gz"), or by kind name.
const InputFormat* input_format_for(const std::string& path);
const OutputFormat* output_format_for(const std::string& path);
const InputFormat* input_format_named(const std::string& kind);
const OutputFormat* output_format_named(const std::string& kind);

// Loads any supported input (by extension), or reports why not.
Result<Loaded> load_input(const std::string& path, const ConvertOptions& options);

// ---- inputs that include inputs (docs/security.md) --------------------------------------------

// While alive, `path` is an input being read on this thread (load_input makes one; so does
// anything that calls a format's load or describe itself). The top input puts its folder (for
// standard input, includes.base_folder) among the folders includes may read; an included input
// takes its relative names from its own folder.
class ReadingInput {
 public:
  ReadingInput(const std::string& path, const ConvertOptions& options);
  ~ReadingInput();
  ReadingInput(const ReadingInput&) = delete;
  ReadingInput& operator=(const ReadingInput&) = delete;
  const ConvertOptions& options() const { return options_; }

 private:
  ConvertOptions options_;
};

// The inputs being read on this thread, outermost first, as their paths were given.
std::vector<std::string> inputs_being_read();

// An input that the one being read includes, named at `where`. One already being read is a cycle,
// an error at `where` naming the chain ("a.combine -> b.combine -> a.combine"); deeper than
// kMaxIncludeDepth is a limit. The input is read on a fresh stack of its own, so that each level
// of including has the whole stack its own bounded recursion needs.
Result<Loaded> load_included_input(const std::string& path, const Location& where,
                                   const ConvertOptions& options);

}  // namespace fapc::cli

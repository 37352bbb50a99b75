#include "fapc/cli_spec.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <sstream>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/pipeline/batch_shard.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::cli {

namespace {

// The subcommands that take the conversion options (docs/cli.md): they load an input and write
// one or more outputs.
#define FAPC_CONVERTERS "compile render plot combine batch"
// Every subcommand that reads inputs (and so takes the resource limits).
#define FAPC_READERS FAPC_CONVERTERS " encode decode verify info"

using VC = ValueCompletion;
using O = OptionSpec;

// The defaults shown in help come from where the libraries define them (ConvertOptions,
// PictureSettings, Limits), never from a second literal here.
const pipeline::ConvertOptions kDefaults{};
std::string limit_default(Limit which) { return limit_value(which, Limits{}); }

// A resource limit's option (docs/security.md): a number from 1 to `max`, its default Limits{}'s;
// inputs' rows name it (reading) or outputs' (writing: the pictures).
OptionSpec limit(const OptionSpec& spec, Limit which, double max, OptionRole role) {
  OptionSpec out = spec.decimal(1, max, limit_default(which));
  out.role = role;
  return out;
}

const std::vector<CommandSpec> kCommands = {
    {"compile", "INPUT -o OUTPUT", "convert any input to any output (the kinds come from the extensions)",
     "Loads INPUT (by its extension or --from: {inputs}) and writes it as OUTPUT, whose kind comes "
     "from its extension or --to: {outputs}. `fapc formats` lists them all with what each carries."},
    {"encode", "INPUT -o OUT.fba", "encode frames as a raw MPEG-4 FBA stream, with the encoder's settings in view",
     "Any input, encoded as an FBA elementary stream with the given quantiser, intra period, ranges and "
     "masks; with --verify the stream is decoded and checked before it is written."},
    {"decode", "{streams} -o OUT.fap", "decode an FBA stream or an .mp4's FBA track to frames",
     "Decodes an FBA stream, bare or in a container ({stream extensions}), and writes the frames, normally as a "
     ".fap file."},
    {"verify", "FILE...", "check that files decode and re-encode to the same bytes",
     "A .fba or .mp4 decodes and encodes again to the same bytes; any other input encodes, decodes within "
     "half a quantiser step and re-encodes identically. Exit status 3 when a check fails."},
    {"info", "FILE", "say what a file holds: kind, frames, fps, the FAPs used and their ranges",
     "One read of FILE: its kind, frame count, frame rate, duration, the FAPs it uses with their ranges, "
     "what the reader saw of the format, and its warnings."},
    {"combine", "EXPRESSION -o OUTPUT", "evaluate an Algebra of Expressions over files (docs/algebra.md)",
     "Evaluates EXPRESSION (quote it) over facial states (.xpr) and animations (any input) and writes "
     "the result; with --states, prints one state as 66 integers instead."},
    {"plot", "INPUT -o OUT.svg|OUT.png|OUT.pdf|OUT.csv", "draw the curves of an input, one panel per parameter",
     "The input's curves (a script's own, or the frames') as a figure (SVG, PNG or PDF) or a .csv of curves "
     "and frames; with --per-clip every clip's own curve too, labelled by its source line."},
    {"render", "INPUT -o {pictures}", "show any input as a face: a picture, a video or a preview page",
     "Draws the face the input animates (docs/render.md): one frame or a contact sheet as .png, a .webm "
     "video, or an .html page that plays it; or the 3D head and its animation as glTF (.glb, .gltf)."},
    {"validate", "FILE...", "check XML documents against the project's schemas",
     "The root element of each file picks the schema (FML, XMT-Omega, XMT-A...); problems go to standard "
     "error with line and column. Exit status 1 when a file has an error."},
    {"batch", "INPUT... -o DIR", "convert many files and folders into a folder, in parallel",
     "Every supported file under the inputs becomes one output per kind in --to, mirroring the input tree "
     "under DIR; a summary line per input, then the counts. A progress bar on a terminal."},
    {"formats", "", "list every input and output kind: extensions, what it carries, which options apply",
     "The pipeline's reader and writer tables as a table (or JSON with --json)."},
    {"faps", "", "list the 68 MPEG-4 face animation parameters",
     "Number, name, unit (FAPU), group, direction, legal range and quantiser step of every FAP, from the "
     "codec's table (or JSON with --json)."},
    {"help", "[COMMAND]", "show the help of fapc or of one subcommand",
     "Without COMMAND, the list of subcommands; with one, its options. The other forms print what "
     "packagers install: the man page, the shell completions, the option tables of docs/cli.md."},
    {"batch-report", "merge REPORT.json...", "merge the JSON reports of a batch's shards; name the jobs with no result",
     "Reads the --report-json files of the tasks of a sharded batch (docs/cluster.md) and says what became "
     "of every planned job: the failures, the jobs no task converted, the shards with no report. Exit status "
     "0 only when every job converted; --report-json and --report write the merged reports."},
};

const std::vector<OptionSpec> kOptions = {
    // Every subcommand.
    {"help", 'h', "", "show this subcommand's help and exit", "*"},
    {"quiet", 'q', "", "print errors only: no warnings, no summaries of warnings, no progress", "*"},
    {"verbose", 'v', "", "also say what is read and written, with timings", "*"},
    // Inputs and outputs.
    {"output", 'o', "FILE", "where the result goes; - is standard output (give --to); a folder for batch",
     "compile encode decode combine plot render batch", false, VC::file},
    {"from", 0, "KIND", "read the input as this kind whatever its name; needed for - (standard input)",
     "compile encode decode verify info plot render", false, VC::input_kinds},
    {"to", 0, "KIND",
     "write this output kind whatever the output's name; needed for -o -; batch takes a "
     "comma-separated list (default fap)",
     "compile decode combine plot render batch", false, VC::output_kinds},
    // Scripts.
    O{"fps", 0, "N", "frames per second of the frames made from a script", FAPC_CONVERTERS}
        .integer(1, 1000, std::to_string(kDefaults.fps))
        .reads(),
    O{"profile", 0, "FILE", "the profile that maps script targets to FAPs (docs/profiles.md)", FAPC_CONVERTERS, false,
      VC::file}
        .reads(),
    O{"lexicon", 0, "FILE",
      "the behaviour lexicon FML-APML and APML intentions, BML face lexemes and Greta references are read by "
      "(docs/intentions.md, docs/bml.md)",
      FAPC_CONVERTERS, false, VC::file}
        .reads(),
    O{"event", 0, "NAME=VALUE", "set an FML event (excl branches, loops; docs/fml.md)", FAPC_CONVERTERS, true}.reads(),
    O{"duration", 0, "S", "end what the source leaves open (indefinite repeats) after S seconds", FAPC_CONVERTERS}
        .decimal(0, 1e7)
        .reads(),
    O{"speech-rate", 0, "N", "words per minute of speech made from text (docs/speech.md)", FAPC_CONVERTERS}
        .decimal(80, 450, shown_number(kDefaults.words_per_minute, Numeric::decimal))
        .reads(),
    O{"voice", 0, "LANG[+VARIANT]", "the speech engine's voice for text without its own (docs/speech.md)",
      FAPC_CONVERTERS}
        .reads(),
    O{"allow-include", 0, "DIR", "a folder includes may read besides the input's own tree (docs/security.md)",
      FAPC_CONVERTERS, true, VC::folder}
        .reads(),
    {"strict", 0, "", "treat every warning as an error; nothing is written", FAPC_CONVERTERS " decode"},
    O{"fap-flavour", 0, "F", "the .fap layout of one player family (docs/fap-files.md, \"Flavours\")",
      FAPC_CONVERTERS " decode", false, VC::fap_flavours}
        .defaults_to(std::string(fap_flavour_name(kDefaults.fap_flavour)))
        .writes(),
    // The FBA encoder.
    O{"quant", 0, "Q", "fap_quant of .fba/.mp4 outputs; 0 is lossless", FAPC_CONVERTERS " encode verify"}
        .integer(0, 31, std::to_string(kDefaults.quant))
        .writes(),
    O{"intra-period", 0, "N", "frames between intra frames; 0 lets the encoder decide",
      FAPC_CONVERTERS " encode verify"}
        .integer(0, 1 << 20, std::to_string(kDefaults.intra_period))
        .writes(),
    O{"ranges", 0, "fit|max", "quantiser ranges fitted to the frames or the largest", FAPC_CONVERTERS " encode verify",
      false, VC::words, "fit max"}
        .defaults_to(kDefaults.ranges)
        .writes(),
    O{"masks", 0, "fit|keep", "FAP masks fitted to the values used or kept as the input gives them",
      FAPC_CONVERTERS " encode verify", false, VC::words, "fit keep"}
        .defaults_to(kDefaults.masks)
        .writes(),
    O{"verify", 0, "", "decode every encoded stream and check it before writing", FAPC_CONVERTERS " encode"}.writes(),
    {"align-planes", 0, "", "start each plane on a byte boundary with a start code (MP4 samples)", "encode"},
    // The face outputs.
    O{"size", 0, "WxH", "picture size of .png/.webm/.html outputs, each side 16 to 7680 pixels", FAPC_CONVERTERS}
        .defaults_to(std::to_string(kDefaults.picture.width) + "x" + std::to_string(kDefaults.picture.height))
        .writes(),
    O{"frame-rate", 0, "N", "frames per second of a .webm", FAPC_CONVERTERS}.integer(1, 120, "the input's").writes(),
    O{"frame", 0, "K", "the frame a .png shows (combine --states: the frame printed)", FAPC_CONVERTERS}
        .integer(0, 1 << 30)
        .writes(),
    O{"time", 0, "T", "the time (seconds) of the frame a .png shows", FAPC_CONVERTERS}.decimal(0, 1e7).writes(),
    O{"sheet", 0, "N", "a .png contact sheet of N frames", FAPC_CONVERTERS}.integer(1, 400).writes(),
    O{"points", 0, "", "mark and number the feature points on a .png", FAPC_CONVERTERS}.writes(),
    O{"view", 0, "2d|3d|both", "what a .html page shows: the 2D face, the 3D head or both", FAPC_CONVERTERS, false,
      VC::words, "2d 3d both"}
        .defaults_to(kDefaults.picture.view)
        .writes(),
    O{"morphs", 0, "faps|arkit", "the morph targets of .glb/.gltf outputs: one per FAP or ARKit's 52 shapes",
      FAPC_CONVERTERS, false, VC::words, "faps arkit"}
        .defaults_to(kDefaults.picture.morphs)
        .writes(),
    // One subcommand each.
    {"per-clip", 0, "", "draw every clip's own curve under the blended one", "plot"},
    {"faps", 0, "LIST", "the FAPs or groups to draw (lips,jaw,3-18,open_jaw)", "plot"},
    {"overlay", 0, "", "draw the chosen curves in one panel with a legend", "plot"},
    {"title", 0, "TEXT", "the figure's title (default: the input's name)", "plot"},
    {"states", 0, "", "print one state of the result as 66 integers instead of writing it", "combine"},
    O{"jobs", 'j', "N", "conversions at a time", "batch"}.integer(1, 256, "one per core"),
    {"report", 0, "FILE", "write a JUnit XML report of the inputs that ran", "batch batch-report", false, VC::file},
    {"report-json", 0, "FILE", "write a JSON report of the inputs that ran (docs/json.md)", "batch batch-report", false,
     VC::file},
    {"keep-going", 0, "", "try every input even after a failure", "batch"},
    {"json", 0, "", "print the results as JSON on standard output", "verify info formats faps"},
    {"man", 0, "", "print the man page (roff)", "help"},
    {"bash-completion", 0, "", "print the bash completion script", "help"},
    {"zsh-completion", 0, "", "print the zsh completion script", "help"},
    {"markdown", 0, "", "print the command and option tables of docs/cli.md", "help"},
    // The resource limits (docs/security.md).
    O{"max-frames", 0, "N", "refuse inputs of more frames", FAPC_READERS}
        .integer(1, 1 << 30, limit_default(Limit::frames))
        .reads(),
    O{"max-runs", 0, "N", "refuse inputs of more runs or clips", FAPC_READERS}
        .integer(1, 1 << 30, limit_default(Limit::runs))
        .reads(),
    limit({"max-decompressed-bytes", 0, "N", "refuse compressed inputs that inflate to more bytes", FAPC_READERS},
          Limit::decompressed_bytes, 1e15, OptionRole::reading),
    limit({"max-expansion", 0, "F", "refuse compressed inputs that inflate more than F times their size", FAPC_READERS},
          Limit::expansion, 1e9, OptionRole::reading),
    // A batch over several machines (docs/cluster.md).
    {"files-from", 0, "LIST",
     "convert the files LIST names, one a line, relative to the one folder INPUT "
     "(default the current folder); - reads standard input",
     "batch", false, VC::file},
    {"shard", 0, "I/N",
     "convert shard I of N (counted from 0) of the planned jobs; default from "
     "SLURM_ARRAY_TASK_ID or JOB_COMPLETION_INDEX",
     "batch"},
    O{"shards", 0, "N", "the shard count, for an index from SLURM_ARRAY_TASK_ID or JOB_COMPLETION_INDEX", "batch"}
        .integer(1, static_cast<double>(pipeline::kMaxShards)),
    {"force", 0, "", "convert every input, also those a completion record says are up to date", "batch"},
    limit({"max-audio-samples", 0, "N", "refuse voice tracks of more samples", FAPC_READERS}, Limit::audio_samples,
          1e15, OptionRole::reading),
    limit({"max-speech-text", 0, "N", "refuse documents with more bytes of talk text", FAPC_READERS},
          Limit::speech_text, 1e12, OptionRole::reading),
    limit({"max-speech-seconds", 0, "S", "refuse documents with more seconds of speech", FAPC_READERS},
          Limit::speech_seconds, 1e9, OptionRole::reading),
    limit({"max-frame-pixels", 0, "N", "refuse pictures of more pixels (.png, .webm, .html)", FAPC_CONVERTERS},
          Limit::frame_pixels, 1e15, OptionRole::writing),
    limit({"max-sheet-pixels", 0, "N", "refuse contact sheets of more pixels", FAPC_CONVERTERS}, Limit::sheet_pixels,
          1e15, OptionRole::writing),
    limit({"max-video-pixels", 0, "N", "refuse videos of more pixels in all, pictures x size", FAPC_CONVERTERS},
          Limit::video_pixels, 1e15, OptionRole::writing),
};

#undef FAPC_READERS
#undef FAPC_CONVERTERS

}  // namespace

bool OptionSpec::applies_to(std::string_view command) const {
  if (commands == "*") return true;
  std::string_view rest = commands;
  while (!rest.empty()) {
    const std::size_t space = rest.find(' ');
    if (rest.substr(0, space) == command) return true;
    if (space == std::string_view::npos) break;
    rest.remove_prefix(space + 1);
  }
  return false;
}

OptionSpec OptionSpec::integer(double min, double max, std::string default_value) const {
  OptionSpec out = *this;
  out.numeric = Numeric::integer;
  out.low = min;
  out.high = max;
  out.shown_default = std::move(default_value);
  return out;
}

OptionSpec OptionSpec::decimal(double min, double max, std::string default_value) const {
  OptionSpec out = integer(min, max, std::move(default_value));
  out.numeric = Numeric::decimal;
  return out;
}

OptionSpec OptionSpec::defaults_to(std::string default_value) const {
  OptionSpec out = *this;
  out.shown_default = std::move(default_value);
  return out;
}

OptionSpec OptionSpec::reads() const {
  OptionSpec out = *this;
  out.role = OptionRole::reading;
  return out;
}

OptionSpec OptionSpec::writes() const {
  OptionSpec out = *this;
  out.role = OptionRole::writing;
  return out;
}

std::string shown_number(double value, Numeric numeric) {
  if (numeric == Numeric::integer) return std::to_string(static_cast<std::int64_t>(value));
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string OptionSpec::value_words() const {
  std::string out;
  const auto add = [&out](const std::string& word) { out += (out.empty() ? "" : " ") + word; };
  if (completion == ValueCompletion::input_kinds)
    for (const auto& f : pipeline::formats().inputs()) add(f.kind);
  if (completion == ValueCompletion::output_kinds)
    for (const auto& f : pipeline::formats().outputs()) add(f.kind);
  if (completion == ValueCompletion::fap_flavours)
    for (char c : fap_flavour_names()) out += c == '|' ? ' ' : c;
  if (completion == ValueCompletion::words) out = std::string(words);
  return out;
}

std::string OptionSpec::value_facts() const {
  std::string facts;
  if (numeric != Numeric::none)
    facts = std::string(numeric == Numeric::integer ? "an integer" : "a number") + " from " +
            shown_number(low, numeric) + " to " + shown_number(high, numeric);
  if (completion == ValueCompletion::words || completion == ValueCompletion::fap_flavours) {
    std::string listed = value_words();
    for (std::size_t at = listed.find(' '); at != std::string::npos; at = listed.find(' ', at + 2))
      listed.replace(at, 1, ", ");
    facts = "one of " + listed;
  }
  if (!shown_default.empty()) facts += (facts.empty() ? "default " : "; default ") + shown_default;
  return facts;
}

std::string OptionSpec::label() const {
  std::string text = short_name ? std::string("-") + short_name + ", --" : "--";
  text += name;
  if (takes_value()) text += " " + std::string(value_name);
  return text;
}

const std::vector<OptionSpec>& option_specs() { return kOptions; }
namespace {

// "IN.fba|IN.mp4": each row's first extension after `prefix`.
template <class Format>
std::string operands_of(const std::vector<const Format*>& rows, const std::string& prefix) {
  std::string out;
  for (const Format* f : rows) out += (out.empty() ? "" : "|") + prefix + f->extensions.front().substr(1);
  return out;
}

// A declared text with the kinds it names taken from the pipeline's tables (the row is the only
// place that knows a format): {inputs} and {outputs} every extension, {streams} and {stream
// extensions} the inputs that hold an FBA stream, {pictures} the outputs that draw the face.
std::string with_kinds(std::string_view declared) {
  namespace fp = pipeline;
  const auto streams = fp::inputs_where([](const fp::InputFormat& f) { return bool(f.verify_stream); });
  const auto pictures = fp::outputs_where([](const fp::OutputFormat& f) { return f.picture; });
  const std::pair<std::string, std::string> names[] = {
      {"{inputs}", fp::extension_list(fp::inputs_where())}, {"{outputs}", fp::extension_list(fp::outputs_where())},
      {"{streams}", operands_of(streams, "IN.")},           {"{stream extensions}", fp::extension_list(streams)},
      {"{pictures}", operands_of(pictures, "OUT.")},
  };
  std::string text(declared);
  for (const auto& [name, value] : names)
    for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + value.size()))
      text.replace(at, name.size(), value);
  return text;
}

}  // namespace

const std::vector<CommandSpec>& command_specs() {
  static const std::vector<CommandSpec> specs = [] {
    static std::deque<std::string> texts;  // what the specs' views see
    std::vector<CommandSpec> made;
    for (CommandSpec c : kCommands) {
      c.operands = texts.emplace_back(with_kinds(c.operands));
      c.details = texts.emplace_back(with_kinds(c.details));
      made.push_back(c);
    }
    return made;
  }();
  return specs;
}

const CommandSpec* find_command_spec(std::string_view name) {
  const auto& specs = command_specs();
  const auto it = std::find_if(specs.begin(), specs.end(), [&](const CommandSpec& c) { return c.name == name; });
  return it == specs.end() ? nullptr : &*it;
}

std::vector<const OptionSpec*> options_of(std::string_view command) {
  std::vector<const OptionSpec*> out;
  for (const OptionSpec& o : kOptions)
    if (o.applies_to(command)) out.push_back(&o);
  return out;
}

const OptionSpec* find_option(std::string_view name) {
  for (const OptionSpec& o : kOptions)
    if (o.name == name) return &o;
  return nullptr;
}

const OptionSpec* find_short_option(char name) {
  for (const OptionSpec& o : kOptions)
    if (name != 0 && o.short_name == name) return &o;
  return nullptr;
}

std::string usage_line(const CommandSpec& command) {
  std::string line = "fapc " + std::string(command.name);
  if (!command.operands.empty()) line += " " + std::string(command.operands);
  return line + " [options]";
}

}  // namespace fapc::cli

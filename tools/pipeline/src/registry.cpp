#include "fapc/pipeline/registry.hpp"

#include <algorithm>
#include <filesystem>
#include <initializer_list>

#include "fapc/codec/did_you_mean.hpp"
#include "fapc/pipeline/codes.hpp"
#include "formats/bridges.hpp"
#include "input_chain.hpp"

// The built-in readers and writers: one function per row, each in its own file in formats/.
// Adding a format: its file, its declaration here and its line in built_in() below.
namespace fapc::pipeline::builtin {
InputFormat fap_input();
InputFormat fba_input();
InputFormat mp4_input();
InputFormat mimic_input();
InputFormat fml_input();
InputFormat xmto_input();
InputFormat combine_input();
InputFormat bml_input();           // format_bml.cpp
InputFormat bml_sequence_input();  // format_bml.cpp: .bmlseq, BML blocks in order
InputFormat xml_input();           // format_xml.cpp: by the root element
InputFormat fml_apml_input();      // format_intent.cpp
InputFormat apml_input();          // format_intent.cpp
InputFormat smil_input();          // format_smil.cpp: Xface SMIL-Agent

OutputFormat fap_output();
OutputFormat fba_output();
OutputFormat mp4_output();
OutputFormat xmta_scene_output();
OutputFormat xmta_commands_output();
OutputFormat curves_json_output();
OutputFormat svg_output();  // the plots (format_svg.cpp)
OutputFormat pdf_output();
OutputFormat csv_output();
OutputFormat timeline_output();
OutputFormat png_output();  // the face (format_face.cpp)
OutputFormat webm_output();
OutputFormat html_output();
OutputFormat wav_output();  // the voice (format_wav.cpp)
OutputFormat glb_output();  // the 3D head (format_gltf.cpp)
OutputFormat gltf_output();
}  // namespace fapc::pipeline::builtin

namespace fapc::pipeline {

namespace {

template <class Format>
const Format* by_extension(const std::vector<Format>& table, const std::string& path) {
  const Format* best = nullptr;
  std::size_t best_length = 0;
  for (const Format& f : table)
    for (const std::string& ext : f.extensions)
      if (ext.size() > best_length && path.ends_with(ext)) {
        best = &f;
        best_length = ext.size();
      }
  return best;
}

template <class Format>
const Format* by_kind(const std::vector<Format>& table, const std::string& kind) {
  for (const Format& f : table)
    if (f.kind == kind) return &f;
  return nullptr;
}

// The one list of built-in formats. Order matters only between entries sharing an extension:
// the longer one wins (".bifs.xmt" before ".xmt"), whatever its place.
// What `fapc formats` says of each: what it carries and the options (as the command line names
// them, without "--") that change how it is read or written.
template <class Format>
Format described(Format format, std::string carries, std::vector<std::string> options) {
  format.carries = std::move(carries);
  format.options = std::move(options);
  return format;
}

const std::vector<std::string> kScriptOptions = {"fps",      "profile",       "duration",  "allow-include",
                                                 "max-runs", "max-expansion", "max-frames"};

// A script reader's options: those of every script, then its own.
std::vector<std::string> script_options(std::initializer_list<std::string> own) {
  std::vector<std::string> options = kScriptOptions;
  options.insert(options.end(), own);
  return options;
}

Registry built_in() {
  Registry r;
  r.add(described(builtin::fap_input(), "frames of FAP values as text (every known flavour; gzip too)",
                  {"max-frames", "max-decompressed-bytes", "max-expansion"}));
  r.add(described(builtin::fba_input(), "a raw MPEG-4 FBA elementary stream (gzip too)",
                  {"max-frames", "max-decompressed-bytes", "max-expansion"}));
  r.add(described(builtin::mp4_input(), "an MPEG-4 file's FBA track", {"max-frames"}));
  r.add(described(builtin::mimic_input(), "a Mimic script: timed actions on animation parameters", kScriptOptions));
  r.add(described(
      builtin::fml_input(), "an FML document: events, excl/par/seq/repeat, talk text",
      script_options({"event", "speech-rate", "voice", "max-speech-text", "max-speech-seconds", "max-audio-samples"})));
  r.add(described(builtin::xmto_input(), "an XMT-Omega document animating FAPs (XMT-A is an output)",
                  script_options({"max-audio-samples"})));
  // Its operands are inputs of any kind, read with the same options.
  r.add(described(builtin::combine_input(), "an Algebra of Expressions over other inputs (docs/algebra.md)",
                  script_options({"event", "lexicon", "voice", "speech-rate", "max-speech-text", "max-speech-seconds",
                                  "max-audio-samples", "max-decompressed-bytes"})));
  r.add(described(builtin::bml_input(), "a BML document: behaviours placed by their sync constraints, speech",
                  script_options({"lexicon", "voice", "speech-rate", "max-speech-text", "max-speech-seconds",
                                  "max-audio-samples"})));
  r.add(described(
      builtin::bml_sequence_input(), "BML documents given in order, placed by their composition (docs/bml.md)",
      script_options({"voice", "speech-rate", "max-speech-text", "max-speech-seconds", "max-audio-samples"})));
  // What the rows it hands documents to read (tests/command/option_rows_test.cpp keeps it so).
  r.add(described(builtin::xml_input(),
                  "an .xml document read by its root: BML, FML, XMT-Omega, FML-APML, APML or SMIL-Agent",
                  script_options({"event", "lexicon", "voice", "speech-rate", "max-speech-text", "max-speech-seconds",
                                  "max-audio-samples"})));
  r.add(described(builtin::fml_apml_input(), "Greta's FML-APML: intentions on a speech's marks, through the lexicon",
                  script_options({"lexicon", "voice", "speech-rate", "max-speech-text", "max-speech-seconds",
                                  "max-audio-samples"})));
  r.add(described(builtin::apml_input(), "APML: intentions marked up over spoken text, through the lexicon",
                  script_options({"lexicon", "voice", "speech-rate", "max-speech-text", "max-speech-seconds",
                                  "max-audio-samples"})));
  r.add(described(
      builtin::smil_input(), "an Xface SMIL-Agent script: speech with marks, affects, eye and head actions",
      script_options({"speech-rate", "voice", "max-speech-text", "max-speech-seconds", "max-audio-samples"})));
  r.add(described(builtin::fap_output(), "frames of FAP values as text (.fap.gz compressed)", {"fap-flavour"}));
  r.add(described(builtin::fba_output(), "a raw MPEG-4 FBA elementary stream",
                  {"quant", "intra-period", "ranges", "masks", "verify"}));
  r.add(described(builtin::mp4_output(), "an MPEG-4 file with a scene and the FBA track",
                  {"quant", "intra-period", "ranges", "masks", "verify"}));
  r.add(described(builtin::xmta_scene_output(), "an XMT-A scene that plays the FBA stream beside it",
                  {"quant", "intra-period", "ranges", "masks"}));
  r.add(described(builtin::xmta_commands_output(), "XMT-A BIFS commands setting the FAPs frame by frame", {}));
  r.add(described(builtin::curves_json_output(), "the curves (time-value lists) of each target, as JSON", {}));
  r.add(described(builtin::svg_output(), "a plot of the curves, one panel per target", {}));
  r.add(described(builtin::pdf_output(), "the same plot as a PDF page", {}));
  r.add(described(builtin::csv_output(), "the curves and frames as comma-separated values", {}));
  r.add(described(builtin::timeline_output(), "the timeline of a script as text, for tests and debugging", {}));
  r.add(described(builtin::png_output(), "a picture of the face: one frame or a contact sheet",
                  {"size", "frame", "time", "sheet", "points", "max-frame-pixels", "max-sheet-pixels"}));
  r.add(described(builtin::webm_output(), "a VP9 video of the face",
                  {"size", "frame-rate", "max-frame-pixels", "max-video-pixels"}));
  r.add(described(builtin::html_output(), "a page that plays the face in a browser",
                  {"size", "frame-rate", "view", "max-frame-pixels", "max-video-pixels"}));
  r.add(described(builtin::wav_output(), "the voice (speech or a recording) as 16-bit PCM WAV",
                  {"voice", "speech-rate", "max-audio-samples"}));
  r.add(described(builtin::tracker_csv_input(), "OpenFace or ARKit CSV, told by its header (docs/bridges.md)",
                  {"fps", "max-frames"}));
  r.add(described(builtin::openface_csv_input(), "OpenFace action units, pose and gaze (docs/bridges.md)",
                  {"fps", "max-frames"}));
  r.add(described(builtin::arkit_csv_input(), "ARKit blendshapes: Live Link Face or MediaPipe names",
                  {"fps", "max-frames"}));
  r.add(described(builtin::arkit_csv_output(),
                  "ARKit blendshapes in Live Link Face's layout; loses FAPs no shape moves", {}));
  r.add(described(builtin::openface_csv_output(), "OpenFace's 17 AU intensities, pose, gaze; loses FAPs no unit moves",
                  {}));
  r.add(
      described(builtin::viseme_json_output(), "FAP 1's visemes as OpenXR names and times; loses every other FAP", {}));
  r.add(described(builtin::viseme_csv_output(), "the viseme track as CSV (start,end,viseme,mpeg4)", {}));
  r.add(described(builtin::glb_output(), "the 3D head with FAP morph targets and the animation, binary glTF 2.0",
                  {"morphs"}));
  r.add(described(builtin::gltf_output(), "the same 3D head and animation as glTF 2.0 JSON", {"morphs"}));
  return r;
}

}  // namespace

const InputFormat* Registry::input_for(const std::string& path) const { return by_extension(inputs_, path); }
const OutputFormat* Registry::output_for(const std::string& path) const { return by_extension(outputs_, path); }
const InputFormat* Registry::input_named(const std::string& kind) const { return by_kind(inputs_, kind); }
const OutputFormat* Registry::output_named(const std::string& kind) const { return by_kind(outputs_, kind); }

const InputFormat* Registry::input_for_xml_root(const std::string& root) const {
  for (const InputFormat& f : inputs_) {
    if (std::find(f.xml_roots.begin(), f.xml_roots.end(), root) != f.xml_roots.end()) return &f;
  }
  return nullptr;
}

const Registry& formats() {
  static const Registry registry = built_in();  // initialised once, thread-safe (C++11 statics)
  return registry;
}

const InputFormat* reader_for(const std::string& path, const ConvertOptions& options) {
  return options.input_kind.empty() ? formats().input_for(path) : formats().input_named(options.input_kind);
}

namespace {

template <class Format>
std::vector<const Format*> rows_where(const std::vector<Format>& table,
                                      const std::function<bool(const Format&)>& keep) {
  std::vector<const Format*> rows;
  for (const Format& f : table)
    if (!keep || keep(f)) rows.push_back(&f);
  return rows;
}

// "a, b or c".
std::string spelt_out(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return out;
}

template <class Format>
std::vector<std::string> kinds_of(const std::vector<const Format*>& rows) {
  std::vector<std::string> kinds;
  for (const Format* f : rows) kinds.push_back(f->kind);
  return kinds;
}

template <class Format>
std::vector<std::string> extensions_of(const std::vector<const Format*>& rows) {
  std::vector<std::string> extensions;
  for (const Format* f : rows)
    for (const std::string& ext : f->extensions)
      if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) extensions.push_back(ext);
  return extensions;
}

// An unknown kind by name (usage: what the caller typed) or by extension (unsupported: the file).
template <class Format>
Diagnostic unknown_kind(const std::vector<Format>& table, const std::string& path, const std::string& kind,
                        bool outputs, ErrorCode named_code) {
  if (!kind.empty()) return make_error(named_code, Location::whole_file(path), unknown_kind_message(kind, outputs));
  const auto rows = rows_where<Format>(table, {});
  const std::string extension = std::filesystem::path(path).extension().string();
  return make_error(codes::format::unknown_extension, Location::whole_file(path),
                    std::string(outputs ? "unknown output kind" : "unknown input kind") + " (expected " +
                        spelt_out(extensions_of(rows)) + ")" +
                        (extension.empty() ? std::string() : did_you_mean(extension, extensions_of(rows))));
}

}  // namespace

std::vector<const InputFormat*> inputs_where(const std::function<bool(const InputFormat&)>& keep) {
  return rows_where(formats().inputs(), keep);
}
std::vector<const OutputFormat*> outputs_where(const std::function<bool(const OutputFormat&)>& keep) {
  return rows_where(formats().outputs(), keep);
}
std::string kind_list(const std::vector<const InputFormat*>& rows) { return spelt_out(kinds_of(rows)); }
std::string kind_list(const std::vector<const OutputFormat*>& rows) { return spelt_out(kinds_of(rows)); }
std::string extension_list(const std::vector<const InputFormat*>& rows) { return spelt_out(extensions_of(rows)); }
std::string extension_list(const std::vector<const OutputFormat*>& rows) { return spelt_out(extensions_of(rows)); }

std::string unknown_kind_message(const std::string& kind, bool outputs) {
  const std::vector<std::string> kinds = outputs ? kinds_of(outputs_where()) : kinds_of(inputs_where());
  return std::string(outputs ? "unknown output kind '" : "unknown input kind '") + kind + "'" +
         did_you_mean(kind, kinds) + " (fapc formats lists them)";
}

Diagnostic unknown_input_kind(const std::string& path, const ConvertOptions& options) {
  return unknown_kind(formats().inputs(), path, options.input_kind, false, codes::format::unknown_input_kind);
}

Diagnostic unknown_output_kind(const std::string& path, const std::string& kind) {
  return unknown_kind(formats().outputs(), path, kind, true, codes::format::unknown_output_kind);
}

Result<Loaded> load(const std::string& path, const ConvertOptions& options) {
  const InputFormat* format = reader_for(path, options);
  if (!format) return unknown_input_kind(path, options);
  const ReadingInput reading(path, options);
  Result<Loaded> loaded = format->load(path, reading.options());
  if (loaded) loaded->origin = path;
  return loaded;
}

}  // namespace fapc::pipeline

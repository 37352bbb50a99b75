#include "fapc/pipeline/registry.hpp"

#include "formats/formats.hpp"
#include "input_chain.hpp"

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
Registry built_in() {
  Registry r;
  r.add(builtin::fap_input());
  r.add(builtin::fba_input());
  r.add(builtin::mp4_input());
  r.add(builtin::mimic_input());
  r.add(builtin::fml_input());
  r.add(builtin::xmto_input());
  r.add(builtin::combine_input());
  r.add(builtin::fap_output());
  r.add(builtin::fba_output());
  r.add(builtin::mp4_output());
  r.add(builtin::xmta_scene_output());
  r.add(builtin::xmta_commands_output());
  r.add(builtin::curves_json_output());
  r.add(builtin::svg_output());
  r.add(builtin::pdf_output());
  r.add(builtin::csv_output());
  r.add(builtin::timeline_output());
  r.add(builtin::png_output());
  r.add(builtin::webm_output());
  r.add(builtin::html_output());
  return r;
}

}  // namespace

const InputFormat* Registry::input_for(const std::string& path) const { return by_extension(inputs_, path); }
const OutputFormat* Registry::output_for(const std::string& path) const { return by_extension(outputs_, path); }
const InputFormat* Registry::input_named(const std::string& kind) const { return by_kind(inputs_, kind); }
const OutputFormat* Registry::output_named(const std::string& kind) const { return by_kind(outputs_, kind); }

const Registry& formats() {
  static const Registry registry = built_in();  // initialised once, thread-safe (C++11 statics)
  return registry;
}

Result<Loaded> load(const std::string& path, const ConvertOptions& options) {
  const InputFormat* format = formats().input_for(path);
  if (!format)
    return make_error(ErrorKind::unsupported, Location{path, 0, 0, -1},
                      "unknown input kind (expected .fap, .fap.gz, .fba, .mp4, .mimic, .fml or .xmt)");
  const ReadingInput reading(path, options);
  Result<Loaded> loaded = format->load(path, reading.options());
  if (loaded) loaded->origin = path;
  return loaded;
}

}  // namespace fapc::pipeline

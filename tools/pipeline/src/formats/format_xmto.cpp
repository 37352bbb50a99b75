// .xmt as an input: XMT-Omega documents (docs/xmt-omega.md). `animation src` loads any other
// registered input through the registry, so a document composes .fap, .fba, Mimic and FML files.
// (.xmt as an output, XMT-A, is format_xmta.cpp's.)
#include <algorithm>
#include <vector>

#include "fapc/pipeline/registry.hpp"
#include "fapc/timeline/timeline_from_frames.hpp"
#include "fapc/xmto/xmto.hpp"
#include "input_chain.hpp"
#include "reader_options.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline::builtin {

namespace {

// Included inputs get their own length: --duration ends the outer document only. A script is
// lowered to its timeline and not rendered (its clips join this document's); an input of frames
// becomes clips holding them.
Result<xmto::IncludedAnimation> load_animation(const std::string& path, const Location& where,
                                               const ConvertOptions& options) {
  ConvertOptions inner = options;
  inner.duration.reset();
  inner.render = false;
  inner.renders_later = false;
  inner.facts = false;
  Result<Loaded> loaded = load_included_input(path, where, inner);
  if (!loaded) {
    // A file that cannot be opened or has no known kind is reported at the element naming it.
    const Diagnostic& error = loaded.error();
    if (error.where.line > 0 || error.where.byte_offset >= 0) return error;
    return retold(error, where, "cannot place '" + path + "': " + error.message);
  }
  xmto::IncludedAnimation included;
  included.timeline = loaded->timeline ? std::move(*loaded->timeline)
                                       : timeline_from_frames(loaded->frames, 0, Location::whole_file(path));
  included.warnings = std::move(loaded->warnings);
  return included;
}

Result<xmto::XmtoDocument> read_document(const std::string& path, const ConvertOptions& options,
                                         const Profile& profile) {
  xmto::XmtoOptions xmto(reader_options(options, &profile));
  // The documents around this one (load() has put this one last): the reader names a cycle
  // among them at the animation element, before the loader is asked.
  xmto.including = inputs_being_read();
  if (!xmto.including.empty()) xmto.including.pop_back();
  xmto.load_animation = [&options](const std::string& included, const Location& where) {
    return load_animation(included, where, options);
  };
  return xmto::load_xmto(path, xmto);
}

nlohmann::ordered_json facts_of(const xmto::XmtoDocument& document) {
  nlohmann::ordered_json out;
  out["format"] = "XMT-Omega";
  if (!document.meta.empty()) {
    nlohmann::ordered_json meta = nlohmann::ordered_json::object();
    for (const auto& [name, content] : document.meta) meta[name] = content;
    out["meta"] = meta;
  }
  out["clips"] = document.timeline.clips.size();
  if (!document.included.empty()) out["included"] = document.included;
  return out;
}

Result<Loaded> load_xmto(const std::string& path, const ConvertOptions& options) {
  return load_script(
      path, options, [&](const Profile& profile) { return read_document(path, options, profile); }, facts_of);
}

}  // namespace

InputFormat xmto_input() {
  InputFormat format{"xmt", {".xmt"}, load_xmto};
  format.timeline = true;
  format.xml_roots = {"xmt-o"};
  return format;
}

}  // namespace fapc::pipeline::builtin

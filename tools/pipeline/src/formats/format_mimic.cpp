// .mimic and .mim inputs: the Mimic compiler, then the shared rendering.
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/transcoder/mimic.hpp"
#include "reader_options.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<Loaded> load_mimic(const std::string& path, const ConvertOptions& options) {
  Result<std::string> source = read_file_bytes(path, options.limits);
  if (!source) return source.error();
  Result<Profile> profile = profile_for(options);
  if (!profile) return profile.error();
  Result<MimicProgram> program = compile_mimic(*source, path, reader_options(options, &*profile));
  // The timeline and the warnings keep nothing of the text: let it go before rendering (a
  // million-action script is 44 MB).
  *source = std::string();
  if (!program) return program.error();
  nlohmann::ordered_json facts = nlohmann::ordered_json::object();
  if (options.facts) {
    facts["clips"] = program->timeline.clips.size();
    facts["timeline_end"] = program->timeline.end();
  }
  return loaded_from_timeline(std::move(program->timeline), path, *profile, options, std::move(program->warnings),
                              std::move(facts));
}

}  // namespace

InputFormat mimic_input() {
  InputFormat format{"mimic", {".mimic", ".mim"}, load_mimic};
  format.timeline = true;
  return format;
}

}  // namespace fapc::pipeline::builtin

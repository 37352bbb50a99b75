// .mimic and .mim inputs: the Mimic compiler, then the shared rendering.
#include "fapc/codec/file_io.hpp"
#include "fapc/registry.hpp"
#include "fapc/timeline_input.hpp"
#include "fapc/transcoder/mimic.hpp"

namespace fapc::cli {

namespace {

Result<Loaded> load_mimic(const std::string& path, const ConvertOptions& options) {
  Result<std::string> source = read_file_bytes(path);
  if (!source) return source.error();
  Result<Profile> profile = profile_for(options);
  if (!profile) return profile.error();
  MimicOptions mimic;
  mimic.profile = &*profile;
  mimic.includes = options.includes;
  Result<MimicProgram> program = compile_mimic(*source, path, mimic);
  if (!program) return program.error();
  return loaded_from_timeline(std::move(program->timeline), path, *profile, options,
                              std::move(program->warnings));
}

Result<nlohmann::ordered_json> describe_mimic(const std::string& path, const ConvertOptions& options) {
  Result<Loaded> loaded = load_mimic(path, options);
  if (!loaded) return loaded.error();
  nlohmann::ordered_json out;
  out["clips"] = loaded->timeline->clips.size();
  out["timeline end"] = loaded->timeline->end();
  return out;
}

const RegisterInput mimic_input{InputFormat{"mimic", {".mimic", ".mim"}, load_mimic, describe_mimic}};

}  // namespace

}  // namespace fapc::cli

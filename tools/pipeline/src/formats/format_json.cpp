// .json output: the curves JSON of docs/cli.md (time-value lists after blending and thinning).
#include "curves_json.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<std::string> write_curves_json(const Loaded& loaded, const std::string&, const ConvertOptions&) {
  // The script's curves when there are some, else the frames' values written as they are read:
  // a long animation's curves are never built (they would be several times the text).
  if (loaded.curves) return curves_json(*loaded.curves);
  return frames_curves_json(loaded.frames);
}

}  // namespace

OutputFormat curves_json_output() {
  return {"json", {".json"}, write_curves_json, /*uses_curves=*/true, /*uses_frames=*/false};
}

}  // namespace fapc::pipeline::builtin

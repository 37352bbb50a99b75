// .timeline output: the shared timeline as text (docs/timeline.md), for debugging front ends.
#include "fapc/pipeline/registry.hpp"

#include "fapc/pipeline/codes.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<std::string> write_timeline(const Loaded& loaded, const std::string& path, const ConvertOptions&) {
  if (!loaded.timeline) {
    return make_error(codes::output::no_timeline, Location::whole_file(path),
                      "this input has frames, not a timeline (.timeline needs a script: " +
                          kind_list(inputs_where([](const InputFormat& f) { return f.timeline; })) + ")");
  }
  return dump(*loaded.timeline);
}

}  // namespace

OutputFormat timeline_output() {
  return {"timeline", {".timeline"}, write_timeline, /*uses_curves=*/false, /*uses_frames=*/false};
}

}  // namespace fapc::pipeline::builtin

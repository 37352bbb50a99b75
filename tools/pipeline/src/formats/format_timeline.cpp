// .timeline output: the shared timeline as text (docs/timeline.md), for debugging front ends.
#include "fapc/registry.hpp"

namespace fapc::cli {

namespace {

Result<std::string> write_timeline(const Loaded& loaded, const std::string& path,
                                   const ConvertOptions&) {
  if (!loaded.timeline) {
    return make_error(Location{path, 0, 0, -1},
                      "this input has frames, not a timeline (.timeline needs Mimic, FML or XMT-Omega)");
  }
  return dump(*loaded.timeline);
}

const RegisterOutput timeline_output{OutputFormat{"timeline", {".timeline"}, write_timeline}};

}  // namespace

}  // namespace fapc::cli

// The 3D head outputs: .glb (binary glTF 2.0) and .gltf (JSON with the buffer embedded), written
// by fapc::head3d from the frames of any input (docs/render.md, "The 3D head").
#include "fapc/head3d/gltf_writer.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<std::string> write_gltf(const Loaded& loaded, const std::string& path, const ConvertOptions& convert,
                               bool binary) {
  head3d::GltfOptions options;
  options.binary = binary;
  options.names = convert.picture.morphs == "arkit" ? head3d::MorphNames::arkit : head3d::MorphNames::faps;
  return head3d::head_gltf(loaded.frames, options, path);
}

// A picture of the face in the table's sense: what `fapc render` writes.
OutputFormat head_output(OutputFormat format) {
  format.picture = true;
  return format;
}

}  // namespace

OutputFormat glb_output() {
  return head_output({"glb", {".glb"}, [](const Loaded& l, const std::string& p, const ConvertOptions& o) {
                        return write_gltf(l, p, o, true);
                      }});
}
OutputFormat gltf_output() {
  return head_output({"gltf", {".gltf"}, [](const Loaded& l, const std::string& p, const ConvertOptions& o) {
                        return write_gltf(l, p, o, false);
                      }});
}

}  // namespace fapc::pipeline::builtin

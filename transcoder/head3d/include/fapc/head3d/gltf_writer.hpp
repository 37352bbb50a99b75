// The .glb / .gltf output: fapc's 3D head with its morph targets, and one animation of the
// sequence (a weights channel and the head's and eyes' rotation channels, one keyframe per frame
// of the input's grid, linear between them). Written with tinygltf (docs/render.md, "The animation").
#pragma once

#include <string>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"

namespace fapc::head3d {

// How the morph targets are named in mesh.extras.targetNames.
enum class MorphNames {
  faps,   // by the FAP's standard name ("open_jaw"), "viseme_PP", "expression_joy"
  arkit,  // ARKit's 52 blendshapes, "jawOpen" (arkit_morphs.hpp)
};

struct GltfOptions {
  bool binary = true;  // .glb; false: .gltf with the buffer embedded as a data: URI
  MorphNames names = MorphNames::faps;
};

// The file's bytes; `where` names the output in errors.
Result<std::string> head_gltf(const FapSequence& sequence, const GltfOptions& options, const std::string& where);

}  // namespace fapc::head3d

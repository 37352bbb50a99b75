// The 3D head's morph targets named and shaped as ARKit's 52 blendshapes (--morphs arkit), so an
// avatar rigged with ARKit names takes the animation. Each shape's target is the sum of its FAPs'
// targets at the amounts of the vocabulary's table (transcoder/vocabulary/data/arkit_faps.tsv);
// a frame's weights are the bounded least-squares fit of the 52 shapes (0..1) to the frame's FAP
// values, the same fit as the ARKit CSV writer's. The eyeLook shapes move no vertex (the eyeballs
// turn on their nodes, as with --morphs faps); their weights are still written for the avatars
// whose rigs turn the eyes by them. docs/render.md, "ARKit morph targets".
#pragma once

#include <vector>

#include "fapc/head3d/head_morphs.hpp"

namespace fapc::head3d {

// In the order of vocabulary::arkit_shape_names(); built once.
const std::vector<MorphTarget>& arkit_targets();

// One weight per shape of arkit_targets() for the frame's FAP values (HeadFrame::faps).
std::vector<double> arkit_weights(const HeadFrame& frame);

}  // namespace fapc::head3d

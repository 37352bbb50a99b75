// Frames (.fap, .fba) as timeline clips, so that a composition (XMT-Omega `animation src`, the
// Algebra over mixed inputs) can place them beside authored clips and shift them in time.
#pragma once

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/timeline/timeline.hpp"

namespace fapc::timeline {

// One clip per FAP and run of consecutive frames carrying it: keys at the frame times, linear
// between them, the last value held to the end of its frame, so that rendering at the sequence's
// own fps gives the frames back exactly. FAP 1 and 2 become viseme.* / expression.* weights with
// step keys. `shift` moves every clip (seconds); `source` labels them.
Timeline timeline_from_frames(const FapSequence& sequence, double shift, const Location& source);

}  // namespace fapc::timeline

// Until the tree names the model fapc::timeline::..., the names are seen from fapc as before.
namespace fapc {
using namespace timeline;
}  // namespace fapc

// Private to the formats: the text of the curves JSON (docs/cli.md, its "Curves JSON" item), from a
// script's curves or straight from frames. Both write the same bytes for the same points.
#pragma once

#include <string>

#include "fapc/codec/fap_sequence.hpp"
#include "fapc/transcoder/curves.hpp"

namespace fapc::pipeline::builtin {

// The curves JSON of a script's (blended, thinned) curves.
std::string curves_json(const Curves& curves);

// The curves JSON of frames: per FAP the frame makes use of, one point per frame where it is
// masked (FAP 1/2 as "viseme"/"expression", their select1 number), as the curves of
// curves_from_frames would print, without building them: the text is measured in a first pass
// over the frames and written in a second, so that memory is the output and nothing else.
std::string frames_curves_json(const FapSequence& sequence);

}  // namespace fapc::pipeline::builtin

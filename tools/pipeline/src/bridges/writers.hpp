// The writers of today's face data (docs/bridges.md, "Outputs"): ARKit CSV in Live Link Face's
// layout, action units in OpenFace's, and the viseme track. Each takes the frames as the face
// shows them (fapc::FaceTrack: FAP 1 and 2 become the mouth and face shapes they stand for).
#pragma once

#include <string>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"

namespace fapc::pipeline::bridges {

std::string write_arkit_csv(const FapSequence& frames);
std::string write_openface_csv(const FapSequence& frames);

// The viseme FAP 1 shows at each frame, by its larger weight; held from the last frame that sends
// it, silence before the first. Consecutive frames of one viseme are one entry.
struct VisemeSpan {
  std::int64_t first_frame = 0;
  std::int64_t end_frame = 0;  // one past the last
  int viseme = 0;
};
std::vector<VisemeSpan> viseme_spans(const FapSequence& frames);
std::string write_viseme_json(const FapSequence& frames);
std::string write_viseme_csv(const FapSequence& frames);

// The FAP sets the bridge outputs can carry: ARKit's shapes, OpenFace's action units, FAP 1 alone.
enum class Carrier { arkit, openface, visemes };

// What `carrier` cannot carry of these frames, as warnings at `output` (empty when nothing is lost).
Diagnostics losses(const FapSequence& frames, Carrier carrier, const std::string& output);

}  // namespace fapc::pipeline::bridges

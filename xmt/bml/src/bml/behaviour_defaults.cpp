#include "bml/behaviour_defaults.hpp"

#include <algorithm>

namespace fapc::bml {

std::array<double, kStandardPoints> default_offsets(const Behaviour& b) {
  switch (b.kind) {
    case BehaviourKind::face_lexeme:
    case BehaviourKind::face_facs:
    case BehaviourKind::lexicon_rows:  // a Greta reference lasts as a display; its rows take fractions of it
      // A facial display: 0.4 s onset to its peak (attackPeak = ready), held, 0.4 s offset; 2 s in
      // all, about a spontaneous expression's length. A shift only has its onset.
      if (b.shift) return {0, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4};
      return {0, 0.4, 0.4, 1.0, 1.6, 1.6, 2.0};
    case BehaviourKind::gaze:
      // A gaze shift of the eyes (and head) takes some 0.3 s; a gaze is held 1.4 s and returns.
      if (b.shift) return {0, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3};
      return {0, 0.3, 0.3, 0.3, 0.3, 1.7, 2.0};
    case BehaviourKind::head_direction:
      return {0, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    case BehaviourKind::head: {
      // One nod or shake cycle lasts 0.6 s, its first extreme (the stroke) 0.4 s in, and a 0.2 s return.
      const double cycles = 0.6 * std::max(1, b.repetition);
      return {0, 0.1, 0.1, 0.4, 0.1 + cycles, 0.1 + cycles, 0.3 + cycles};
    }
    case BehaviourKind::wait:
      return {0, 0, 0, 0, 0, 0, 0};
    case BehaviourKind::not_drawn:
      // A gesture's phases, as the BML 1.0 text draws them: preparation, stroke, retraction.
      return {0, 0.3, 0.4, 0.6, 0.8, 1.2, 1.5};
    case BehaviourKind::lips:
      // One viseme of a recording: about a tenth of a second, held whole (start = ready,
      // relax = end, as NVBG writes them).
      return {0, 0, 0, 0.05, 0.1, 0.1, 0.1};
    case BehaviourKind::speech: {
      const double d = b.speech ? b.speech->duration : 0.0;
      return {0, 0, 0, 0, d, d, d};
    }
  }
  return {};
}

}  // namespace fapc::bml

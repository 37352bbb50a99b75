#include "fapc/codec/fap_sequence.hpp"

namespace fapc {

bool FapFrame::same_content(const FapFrame& other) const {
  if (mask != other.mask) return false;
  if (has(1) && viseme != other.viseme) return false;
  if (has(2) && expression != other.expression) return false;
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (has(fap) && value(fap) != other.value(fap)) return false;
  return true;
}

double FapSequence::duration_seconds() const {
  if (frames.empty() || fps <= 0) return 0.0;
  return static_cast<double>(frames.back().number + 1) / fps;
}

}  // namespace fapc

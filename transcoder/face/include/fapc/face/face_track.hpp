// What the face shows at each moment of a FAP sequence: every FAP's value held from the last frame
// that carried it (0 before), with FAP 1 (viseme) and FAP 2 (expression) turned into the low-level
// FAPs of their displacement sets and added, blended as the stream's fields say.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc::face {

// Index i is FAP i+1, in FAP units; slots 0 and 1 (FAP 1 and 2) stay 0 once blended in.
using FapValues = std::array<double, kFapCount>;

// The low-level FAPs of viseme 1..14 and expression 1..6 at full strength (their tables are in
// docs/render.md); zeros for 0 and out-of-range numbers.
const FapValues& viseme_displacements(int viseme);
const FapValues& expression_displacements(int expression);

// FAP 1's and 2's fields turned into low-level values: viseme1 x blend/63 + viseme2 x
// (1 - blend/63); expression1 x intensity1/63 + expression2 x intensity2/63.
FapValues high_level_values(const VisemeFields& viseme, bool has_viseme, const ExpressionFields& expression,
                            bool has_expression);

class FaceTrack {
 public:
  explicit FaceTrack(const FapSequence& sequence);

  int fps() const { return fps_; }
  // Frames on the sequence's grid: the last frame number + 1 (0 for an empty sequence).
  std::int64_t frame_count() const { return frame_count_; }
  double duration_seconds() const { return fps_ > 0 ? static_cast<double>(frame_count_) / fps_ : 0; }

  // The values shown at grid frame `number` (held from the last frame at or before it).
  const FapValues& at_frame(std::int64_t number) const;
  // The values shown at time `seconds`: the grid frame that contains that instant.
  const FapValues& at_time(double seconds) const;
  // FAPs (1-based numbers, 3..68) that are not 0 somewhere.
  std::vector<int> moving_faps() const;

 private:
  int fps_;
  std::int64_t frame_count_ = 0;
  std::vector<std::int64_t> numbers_;  // the sequence's frame numbers, ascending
  std::vector<FapValues> shown_;       // what each of them shows
  FapValues rest_{};                   // before the first frame
};

}  // namespace fapc::face

// The encoder's decisions, made before any bit is written (docs/fba.md): where intra planes go,
// the quantised symbols of every plane (closed-loop prediction from the decoder's own
// reconstruction, fba-bitstream.md section 6.7), and the ranges each intra plane signals.
// A group of planes ("GOP") is one intra plane and the predictive planes that follow it.
// Private to fapcodec.
#pragma once

#include <bitset>
#include <cstdint>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fba.hpp"
#include "fba/face_state.hpp"

namespace fapc::fba {

struct Gop {
  std::size_t first = 0;  // frames [first, end) of the sequence
  std::size_t end = 0;
  std::bitset<kFapCount> mask;
  std::vector<int> faps;  // masked FAPs 3..68, ascending: the coding order
  // Per frame, faps.size() quantised values: the value itself in the intra plane, the difference
  // from the previous reconstruction in predictive planes. |q| <= 1860 fits 16 bits.
  std::vector<std::int16_t> symbols;
  // Per frame, the 7 FAP 1/2 fields in coding order (value or difference, quantised when the
  // field is); fields of an unmasked FAP 1 or 2 are 0.
  std::vector<std::int16_t> fields;
  RangeCodes codes{};  // the four range lists the intra plane signals
};

// How often each FAP of a group has coded each small difference, to choose between two equally
// good reconstructions. Differences beyond +-64 count as never seen.
class DifferenceCounts {
 public:
  void clear(std::size_t faps) { counts_.assign(faps * kWidth, 0); }
  std::uint32_t count(std::size_t j, std::int64_t q) const {
    return q >= -kSpan && q < kSpan ? counts_[j * kWidth + static_cast<std::size_t>(q + kSpan)] : 0;
  }
  void add(std::size_t j, std::int64_t q) {
    if (q >= -kSpan && q < kSpan) ++counts_[j * kWidth + static_cast<std::size_t>(q + kSpan)];
  }

 private:
  static constexpr std::int64_t kSpan = 64;
  static constexpr std::size_t kWidth = 2 * kSpan;
  std::vector<std::uint32_t> counts_;  // [fap position in the group][difference + kSpan]
};

class GopPlanner {
 public:
  GopPlanner(const FapSequence& sequence, const FbaEncodeOptions& options);

  bool has_next() const { return next_ < frames_.size(); }
  // The next group, from the current frame up to the next frame that needs an intra plane.
  // Fails when an intra value lies beyond the largest range the bitstream can carry.
  Result<Gop> next();

 private:
  bool needs_intra(std::size_t k, std::size_t gop_first) const;
  Status quantise_intra(std::size_t k, Gop& gop);
  bool quantise_predictive(std::size_t k, Gop& gop);  // false: a difference needs a wider range
  bool within(std::int64_t q) const { return q <= limit_ && q >= -limit_; }
  void fit_ranges(Gop& gop) const;

  const std::vector<FapFrame>& frames_;
  FbaEncodeOptions options_;
  FaceState quant_;  // only fap_quant, steps and field limits are used
  std::int32_t limit_;  // the largest |q| any range can carry: 31 * 60 / scaler
  std::size_t next_ = 0;
  std::array<std::int64_t, kFapCount> levels_{};  // reconstructions as multiples of their step
  std::vector<std::int64_t> steps_;                // of the group's FAPs, in coding order
  std::array<std::int32_t, kCodedFieldCount> recon_fields_{};
  std::vector<std::int16_t> scratch_;
  DifferenceCounts history_;  // of the current group
};

}  // namespace fapc::fba

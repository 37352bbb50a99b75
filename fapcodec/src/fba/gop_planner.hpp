// The encoder's decisions, made before any bit is written (docs/fba.md): where intra planes go,
// the quantised symbols of every plane (closed-loop prediction from the decoder's own
// reconstruction, docs/fba-bitstream.md section 6.7), and the ranges each intra plane signals.
// A group of planes ("GOP") is one intra plane and the predictive planes that follow it.
// Private to fapcodec.
#pragma once

#include <bitset>
#include <cstdint>
#include <optional>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fba.hpp"
#include "fba/face_state.hpp"
#include "fba/frame_window.hpp"
#include "fba/level_chooser.hpp"
#include "fba/level_rule.hpp"

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

// Plans groups over a window of frames that the caller fills as frames come (the encoder
// streams: it holds one group and the frame after it, never the sequence). The group always starts
// at the window's first frame; the caller removes a group's frames once it has written them.
class GopPlanner {
 public:
  GopPlanner(const FrameWindow& window, const FbaEncodeOptions& options);

  // The next group, from the window's first frame up to the next frame that needs an intra plane:
  // a mask change, the intra period, or a difference no range can carry. Empty while the window
  // does not reach that frame yet and more frames are to come (`input_ended` false); the scan goes
  // on from where it stopped at the next call, so a group costs one scan however often it is
  // asked for. Fails when an intra value lies beyond the largest range the bitstream can carry.
  Result<std::optional<Gop>> next(bool input_ended);

 private:
  Status begin_group();
  Gop complete_group(std::size_t end);
  bool needs_intra(std::size_t k, std::size_t gop_first) const;
  // The standard's rounding of every FAP of the group in frame k, into `levels`.
  void nearest_levels(std::size_t k, const Gop& gop, std::vector<std::int64_t>& levels) const;
  // Whether every difference of nearest levels from frame k - 1 to frame k fits a range.
  bool differences_fit(std::size_t k, const Gop& gop);
  Status check_intra(const Gop& gop) const;
  void choose_levels(Gop& gop, std::size_t frames);
  void quantise_fields(std::size_t k, bool intra, Gop& gop);
  void fit_ranges(Gop& gop) const;
  bool within(std::int64_t q) const { return q <= limit_ && q >= -limit_; }

  const FrameWindow& frames_;  // the window
  FbaEncodeOptions options_;
  std::optional<Gop> current_;                            // the group being scanned; begun, not complete
  std::size_t scan_ = 0;                                  // the next frame of the window to scan
  FaceState quant_;                                       // only fap_quant, steps and field limits are used
  std::int32_t limit_;                                    // the largest |q| any range can carry: 31 * 60 / scaler
  const std::size_t next_ = 0;                            // groups start at the window's first frame
  std::vector<LevelRule> rules_;                          // of the group's FAPs, in coding order
  std::vector<std::int64_t> bounds_;                      // and the value differences whose levels surely fit
  std::vector<std::int64_t> nearest_, previous_nearest_;  // nearest levels of two frames
  std::vector<LevelOptions> column_;                      // one FAP's choices over the group
  std::vector<std::int64_t> levels_;                      // and its chosen levels
  LevelChooser chooser_;
  std::array<std::int32_t, kCodedFieldCount> recon_fields_{};
};

}  // namespace fapc::fba

#include "fba/gop_planner.hpp"

#include <algorithm>
#include <string>

#include "fba/fba_quant.hpp"

namespace fapc::fba {

namespace {

std::array<int, kCodedFieldCount> coded_fields(const FapFrame& f) {
  return {f.viseme.select1,     f.viseme.select2,        f.viseme.blend,
          f.expression.select1, f.expression.intensity1, f.expression.select2,
          f.expression.intensity2};
}

bool field_masked(const std::bitset<kFapCount>& mask, int field) {
  return mask.test(field < kVisemeFields ? 0 : 1);
}

}  // namespace

GopPlanner::GopPlanner(const FapSequence& sequence, const FbaEncodeOptions& options)
    : frames_(sequence.frames), options_(options) {
  quant_.fap_quant = options.quant;
  limit_ = kMaxRangeValue * kRangeDelta / quant_.range_scaler();
}

bool GopPlanner::needs_intra(std::size_t k, std::size_t gop_first) const {
  if (frames_[k].mask != frames_[k - 1].mask) return true;  // masks travel only in intra planes
  return options_.intra_period > 0 && k - gop_first >= static_cast<std::size_t>(options_.intra_period);
}

Status GopPlanner::quantise_intra(std::size_t k, Gop& gop) {
  const FapFrame& frame = frames_[k];
  for (std::size_t j = 0; j < gop.faps.size(); ++j) {
    const int fap = gop.faps[j];
    const std::int64_t step = steps_[j];
    const std::int64_t q = quantise(frame.value(fap), step);
    if (q > limit_ || q < -limit_) {
      const FapInfo& info = fap_table()[FaceState::index(fap)];
      return make_error(Location{}, "frame " + std::to_string(frame.number) + ": FAP " +
                                        std::to_string(fap) + " (" + std::string(info.name) +
                                        ") value " + std::to_string(frame.value(fap)) +
                                        " is beyond the largest range the bitstream carries (+-" +
                                        std::to_string(limit_ * std::max<std::int64_t>(step, 1)) +
                                        " at fap_quant " + std::to_string(options_.quant) + ")");
    }
    gop.symbols.push_back(static_cast<std::int16_t>(q));
    levels_[FaceState::index(fap)] = q;
  }
  const auto fields = coded_fields(frame);
  for (int field = 0; field < kCodedFieldCount; ++field) {
    const auto f = static_cast<std::size_t>(field);
    if (!field_masked(gop.mask, field)) {
      gop.fields.push_back(0);
      continue;
    }
    const std::int64_t q = quantise(fields[f], quant_.field_step(field));
    gop.fields.push_back(static_cast<std::int16_t>(q));
    recon_fields_[f] = static_cast<std::int32_t>(dequantise(q, quant_.field_step(field)));
  }
  return ok_status();
}

bool GopPlanner::quantise_predictive(std::size_t k, Gop& gop) {
  const FapFrame& frame = frames_[k];
  scratch_.clear();
  const auto& levels = levels_;  // changed only once the whole frame fits
  for (std::size_t j = 0; j < gop.faps.size(); ++j) {
    const std::size_t i = FaceState::index(gop.faps[j]);
    const std::int64_t step = steps_[j];
    const std::int64_t value = frame.values[i];
    // Reconstructions stay on the lattice step * Z (the level is the multiple). Every lattice
    // point within half a step of the value is a correct reconstruction: one, or two when the
    // value lies exactly half way (even steps only). Of two, the planner takes the difference
    // this group has coded more often so far, which the adaptive model codes in fewer bits; on a
    // tie, the reference's rule: the quantised difference, which rounds half away from zero (half
    // a step down to 0). Decoded frames sit on the lattice and leave no choice, so re-encoding
    // them takes the same path. Whether a range can carry the frame is judged on these
    // differences too.
    const std::int64_t level = step <= 1 ? value : quantise(value, step);
    std::int64_t q = level - levels[i];
    if (step % 2 == 0 && step != 0 && 2 * std::llabs(value - level * step) == step) {
      std::int64_t other = (value > level * step ? level + 1 : level - 1) - levels[i];
      if (quantise(value - levels[i] * step, step) == other) std::swap(q, other);
      if (history_.count(j, other) > history_.count(j, q)) std::swap(q, other);
      if (!within(q)) q = other;
    }
    if (!within(q)) return false;
    scratch_.push_back(static_cast<std::int16_t>(q));
  }
  for (std::size_t j = 0; j < scratch_.size(); ++j) {
    levels_[FaceState::index(gop.faps[j])] += scratch_[j];
    history_.add(j, scratch_[j]);
  }
  gop.symbols.insert(gop.symbols.end(), scratch_.begin(), scratch_.end());
  const auto fields = coded_fields(frame);
  for (int field = 0; field < kCodedFieldCount; ++field) {
    const auto f = static_cast<std::size_t>(field);
    if (!field_masked(gop.mask, field)) {
      gop.fields.push_back(0);
      continue;
    }
    // Blends and intensities stay within -B..B: both values lie in 0..63 (B * step >= 63).
    const std::int64_t q = quantise(fields[f] - recon_fields_[f], quant_.field_step(field));
    gop.fields.push_back(static_cast<std::int16_t>(q));
    recon_fields_[f] += static_cast<std::int32_t>(dequantise(q, quant_.field_step(field)));
  }
  return true;
}

void GopPlanner::fit_ranges(Gop& gop) const {
  const std::size_t n = gop.faps.size();
  const int scaler = quant_.range_scaler();
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = FaceState::index(gop.faps[j]);
    if (options_.ranges == FbaRangeMode::max) {
      for (auto& list : gop.codes) list[i] = kMaxRangeValue;
      continue;
    }
    const std::int64_t intra = gop.symbols[j];
    std::int64_t pred_high = 0, pred_low = 0;
    for (std::size_t at = n + j; at < gop.symbols.size(); at += n) {
      pred_high = std::max<std::int64_t>(pred_high, gop.symbols[at]);
      pred_low = std::min<std::int64_t>(pred_low, gop.symbols[at]);
    }
    const auto code = [scaler](std::int64_t magnitude) {
      return static_cast<std::uint8_t>(range_value_for(magnitude, scaler));
    };
    gop.codes[kIntraMax][i] = code(std::max<std::int64_t>(intra, 0));
    gop.codes[kIntraMin][i] = code(std::max<std::int64_t>(-intra, 0));
    gop.codes[kPredMax][i] = code(pred_high);
    gop.codes[kPredMin][i] = code(-pred_low);
  }
  // The reference decoder takes an intra range of [0, 0] for FAP 4 as "no ranges yet" and
  // re-applies its default table (section 13, item 13): never signal it.
  constexpr std::size_t kFap4 = 3;
  if (gop.mask.test(kFap4) && gop.codes[kIntraMax][kFap4] == 0 && gop.codes[kIntraMin][kFap4] == 0)
    gop.codes[kIntraMax][kFap4] = 1;
}

Result<Gop> GopPlanner::next() {
  Gop gop;
  gop.first = next_;
  gop.mask = frames_[next_].mask;
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap)
    if (gop.mask.test(FaceState::index(fap))) gop.faps.push_back(fap);
  steps_.clear();
  for (const int fap : gop.faps) steps_.push_back(quant_.step(fap));
  history_.clear(gop.faps.size());
  if (auto status = quantise_intra(next_, gop); !status) return status.error();
  std::size_t k = next_ + 1;
  while (k < frames_.size() && !needs_intra(k, gop.first) && quantise_predictive(k, gop)) ++k;
  gop.end = next_ = k;
  fit_ranges(gop);
  return gop;
}

}  // namespace fapc::fba

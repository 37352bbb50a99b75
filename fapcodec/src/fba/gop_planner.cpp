#include "fba/gop_planner.hpp"

#include <algorithm>
#include <string>

#include "fapc/codec/codes.hpp"
#include "fba/fba_quant.hpp"
#include "fba/level_rule.hpp"

namespace fapc::fba {

namespace {

std::array<int, kCodedFieldCount> coded_fields(const FrameWindow::View& f) {
  return {f.viseme.select1,        f.viseme.select2,     f.viseme.blend,         f.expression.select1,
          f.expression.intensity1, f.expression.select2, f.expression.intensity2};
}

bool field_masked(const std::bitset<kFapCount>& mask, int field) { return mask.test(field < kVisemeFields ? 0 : 1); }

}  // namespace

GopPlanner::GopPlanner(const FrameWindow& window, const FbaEncodeOptions& options)
    : frames_(window), options_(options) {
  quant_.fap_quant = options.quant;
  limit_ = kMaxRangeValue * kRangeDelta / quant_.range_scaler();
}

bool GopPlanner::needs_intra(std::size_t k, std::size_t gop_first) const {
  if (frames_[k].mask != frames_[k - 1].mask) return true;  // masks travel only in intra planes
  return options_.intra_period > 0 && k - gop_first >= static_cast<std::size_t>(options_.intra_period);
}

void GopPlanner::nearest_levels(std::size_t k, const Gop& gop, std::vector<std::int64_t>& levels) const {
  levels.clear();
  const std::int32_t* values = frames_.masked_values(k);  // the group's FAPs, in order
  for (std::size_t j = 0; j < gop.faps.size(); ++j) levels.push_back(rules_[j].nearest(values[j]));
}

bool GopPlanner::differences_fit(std::size_t k, const Gop& gop) {
  // A nearest level lies within 1 of value / step (half a step of rounding, and the legal cap
  // moves it by less than one step more), so two levels differ by at most |a - b| / step + 2:
  // differences of values within `bounds_` need no rounding. Only a frame that jumps further
  // (hardly ever) has its levels and those of the frame before worked out.
  const std::int32_t* now = frames_.masked_values(k);  // the group's FAPs, in order
  const std::int32_t* before = frames_.masked_values(k - 1);
  bool near = true;
  for (std::size_t j = 0; j < gop.faps.size(); ++j) {
    const std::int64_t d = std::int64_t{now[j]} - before[j];
    near = near && d <= bounds_[j] && d >= -bounds_[j];
  }
  if (near) return true;
  nearest_levels(k - 1, gop, previous_nearest_);
  nearest_levels(k, gop, nearest_);
  for (std::size_t j = 0; j < nearest_.size(); ++j)
    if (!within(nearest_[j] - previous_nearest_[j])) return false;
  return true;
}

Status GopPlanner::check_intra(const Gop& gop) const {
  const FrameWindow::View frame = frames_[gop.first];
  for (std::size_t j = 0; j < gop.faps.size(); ++j) {
    if (within(nearest_[j])) continue;
    const int fap = gop.faps[j];
    const FapInfo& info = fap_table()[FaceState::index(fap)];
    return make_error(codes::fba::value_beyond_range, options_.locate ? options_.locate(frame.number, fap) : Location{},
                      "frame " + std::to_string(frame.number) + ": FAP " + std::to_string(fap) + " (" +
                          std::string(info.name) + ") value " + std::to_string(frame.value(fap)) +
                          " is beyond the largest range the bitstream carries (+-" +
                          std::to_string(limit_ * std::max<std::int64_t>(rules_[j].step(), 1)) + " at fap_quant " +
                          std::to_string(options_.quant) + ")");
  }
  return ok_status();
}

void GopPlanner::choose_levels(Gop& gop, std::size_t frames) {
  const std::size_t n = gop.faps.size();
  gop.symbols.resize(frames * n);
  column_.resize(frames);
  levels_.resize(frames);
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t t = 0; t < frames; ++t) column_[t] = rules_[j].options(frames_.masked_values(gop.first + t)[j]);
    chooser_.choose(column_, limit_, quant_.range_scaler(), levels_);
    gop.symbols[j] = static_cast<std::int16_t>(levels_[0]);
    for (std::size_t t = 1; t < frames; ++t)
      gop.symbols[t * n + j] = static_cast<std::int16_t>(levels_[t] - levels_[t - 1]);
  }
}

void GopPlanner::quantise_fields(std::size_t k, bool intra, Gop& gop) {
  const auto fields = coded_fields(frames_[k]);
  for (int field = 0; field < kCodedFieldCount; ++field) {
    const auto f = static_cast<std::size_t>(field);
    if (!field_masked(gop.mask, field)) {
      gop.fields.push_back(0);
      continue;
    }
    // Predictive blends and intensities stay within -B..B: both values lie in 0..63 (B * step >= 63).
    // A blend or intensity is never reconstructed above 63, which an even step would give 63
    // (64 at fap_quant 2): one step lower instead (docs/fba.md 2, "Legal ranges").
    const std::int32_t base = intra ? 0 : recon_fields_[f];
    const std::int64_t step = quant_.field_step(field);
    std::int64_t q = quantise(fields[f] - base, step);
    if (quant_.field_quantised(field))
      while (base + dequantise(q, step) > kLargestFieldValue) --q;
    gop.fields.push_back(static_cast<std::int16_t>(q));
    recon_fields_[f] = base + static_cast<std::int32_t>(dequantise(q, step));
  }
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
  // re-applies its default table (docs/fba-bitstream.md section 13, item 13): never signal it.
  constexpr std::size_t kFap4 = 3;
  if (gop.mask.test(kFap4) && gop.codes[kIntraMax][kFap4] == 0 && gop.codes[kIntraMin][kFap4] == 0)
    gop.codes[kIntraMax][kFap4] = 1;
}

Status GopPlanner::begin_group() {
  Gop& gop = current_.emplace();
  gop.first = next_;
  gop.mask = frames_[next_].mask;
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap)
    if (gop.mask.test(FaceState::index(fap))) gop.faps.push_back(fap);
  rules_.clear();
  bounds_.clear();
  for (const int fap : gop.faps) {
    rules_.emplace_back(quant_.step(fap), fap_table()[FaceState::index(fap)].legal_max());
    bounds_.push_back((limit_ - 2) * std::max<std::int64_t>(rules_.back().step(), 1));
  }
  nearest_levels(next_, gop, nearest_);
  if (auto status = check_intra(gop); !status) return status;
  scan_ = next_ + 1;
  return ok_status();
}

Result<std::optional<Gop>> GopPlanner::next(bool input_ended) {
  if (frames_.size() <= next_) return std::optional<Gop>{};
  if (!current_)
    if (auto status = begin_group(); !status) return status.error();
  // The group ends where the next intra plane must go. Whether a range can carry each difference
  // is judged on the nearest levels; the chooser then keeps to the same bound.
  for (; scan_ < frames_.size(); ++scan_) {
    if (needs_intra(scan_, current_->first) || !differences_fit(scan_, *current_))
      return std::optional<Gop>{complete_group(scan_)};
  }
  if (input_ended) return std::optional<Gop>{complete_group(scan_)};
  return std::optional<Gop>{};
}

Gop GopPlanner::complete_group(std::size_t end) {
  Gop gop = std::move(*current_);
  current_.reset();
  choose_levels(gop, end - next_);
  for (std::size_t f = next_; f < end; ++f) quantise_fields(f, f == next_, gop);
  gop.end = end;
  fit_ranges(gop);
  return gop;
}

}  // namespace fapc::fba

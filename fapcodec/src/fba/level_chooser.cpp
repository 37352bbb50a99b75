#include "fba/level_chooser.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <math.h>  // lgamma_r

#include "fba/fba_quant.hpp"

namespace fapc::fba {

namespace {

// ln Γ(x). std::lgamma stores the sign of Γ(x) in the global `signgam` (POSIX), a data race when
// several threads encode at once (a parallel batch; ThreadSanitizer reports it); lgamma_r
// returns the sign through a pointer instead.
double log_gamma(double x) {
  int sign = 0;
  return ::lgamma_r(x, &sign);
}

// A second round still pays a little on real files (0.3 bits per frame on the Xface emotion
// files); more rounds gain nothing measurable.
constexpr int kMaxReplans = 2;
constexpr double kInfinite = std::numeric_limits<double>::infinity();
constexpr std::int64_t kReach = 4;

std::int64_t side(std::int64_t magnitude, int scaler) {
  return range_value_for(magnitude, scaler) * kRangeDelta / scaler;
}

// What the uniform intra model costs for `level`: log2 of its fitted intra alphabet.
double intra_bits(std::int64_t level, int scaler) {
  return std::log2(static_cast<double>(fitted_alphabet(std::min<std::int64_t>(level, 0), level, scaler)));
}

std::int64_t level_of(const LevelOptions& option, int state) { return state == 0 ? option.nearest : option.other; }

bool has_choice(const LevelOptions& option) { return option.other != option.nearest; }

}  // namespace

std::int64_t fitted_alphabet(std::int64_t low, std::int64_t high, int range_scaler) {
  return side(std::max<std::int64_t>(high, 0), range_scaler) + side(std::max<std::int64_t>(-low, 0), range_scaler) + 1;
}

void LevelChooser::choose(std::span<const LevelOptions> options, std::int64_t limit, int range_scaler,
                          std::span<std::int64_t> levels) {
  scaler_ = range_scaler;
  // The steps a choice can change: into or out of a frame with two choices. Between two frames
  // without a choice every plan takes the same step, which shifts all costs alike and so decides
  // nothing. Only the levels of the steps' frames (and of frame 0) are ever read or changed below:
  // every other frame keeps its nearest level.
  steps_.clear();
  std::int64_t fixed_low = 0, fixed_high = 0;
  for (std::size_t t = 0; t < options.size(); ++t) {
    levels[t] = options[t].nearest;
    if (t == 0) continue;
    if (has_choice(options[t]) || has_choice(options[t - 1])) {
      steps_.push_back(t);
    } else {
      const std::int64_t d = options[t].nearest - options[t - 1].nearest;
      fixed_low = std::min(fixed_low, d);
      fixed_high = std::max(fixed_high, d);
    }
  }
  if (steps_.empty()) return;
  count_fixed(options, fixed_low, fixed_high);
  double cost = exact_cost(levels);  // leaves the counts of `levels` for the first replan
  trial_.resize(levels.size());
  for (int round = 0; round < kMaxReplans; ++round) {
    if (!replan(options, limit, trial_)) break;
    const double trial_cost = exact_cost(trial_);  // and those of the trial for the next
    if (!(trial_cost < cost)) break;
    cost = trial_cost;
    levels[0] = trial_[0];
    for (const std::size_t t : steps_) levels[t - 1] = trial_[t - 1], levels[t] = trial_[t];
  }
}

void LevelChooser::count_fixed(std::span<const LevelOptions> options, std::int64_t low, std::int64_t high) {
  // The steps not in steps_ join two frames without a choice: the same in every plan.
  fixed_low_ = low;
  fixed_high_ = high;
  fixed_counts_.assign(static_cast<std::size_t>(high - low + 1), 0);
  for (std::size_t t = 1; t < options.size(); ++t)
    if (!has_choice(options[t]) && !has_choice(options[t - 1]))
      ++fixed_counts_[static_cast<std::size_t>(options[t].nearest - options[t - 1].nearest - low)];
}

void LevelChooser::count(std::span<const std::int64_t> levels) {
  // The fixed steps' counts, counted once per choice, plus those of the steps a plan chooses.
  std::int64_t low = fixed_low_, high = fixed_high_;
  for (const std::size_t t : steps_) {
    low = std::min(low, levels[t] - levels[t - 1]);
    high = std::max(high, levels[t] - levels[t - 1]);
  }
  low_ = low;
  counts_.assign(static_cast<std::size_t>(high - low + 1), 0);
  std::copy(fixed_counts_.begin(), fixed_counts_.end(), counts_.begin() + (fixed_low_ - low));
  for (const std::size_t t : steps_) ++counts_[static_cast<std::size_t>(levels[t] - levels[t - 1] - low)];
  alphabet_ = fitted_alphabet(low, high, scaler_);
}

double LevelChooser::exact_cost(std::span<const std::int64_t> levels) {
  count(levels);
  const auto symbols = static_cast<double>(levels.size() - 1);
  const auto alphabet = static_cast<double>(alphabet_);
  double bits = (log_gamma(symbols + alphabet) - log_gamma(alphabet)) / std::log(2.0);
  for (const std::uint32_t n : counts_)
    if (n > 1) bits -= logs_.factorial(n);
  return bits + intra_bits(levels[0], scaler_);
}

bool LevelChooser::replan(std::span<const LevelOptions> options, std::int64_t limit, std::span<std::int64_t> levels) {
  // Prices from the counts count() left: the adaptive model's long-run cost of each difference,
  // with half a count for differences not seen yet (a Krichevsky-Trofimov style estimate).
  const double log_total = std::log2(static_cast<double>(levels.size() - 1) + 0.5 * static_cast<double>(alphabet_));
  // Every level is within one of its nearest level, and so are those of the plan counted, so any
  // step a plan can take lies within kReach of a counted one: prices cover that window, with
  // steps no range can carry priced out.
  const double unseen = log_total + 1;
  price_.assign(counts_.size() + 2 * kReach, unseen);
  for (std::size_t i = 0; i < price_.size(); ++i) {
    const std::int64_t d = static_cast<std::int64_t>(i) - kReach + low_;
    if (d > limit || d < -limit)
      price_[i] = kInfinite;
    else if (i >= kReach && i - kReach < counts_.size())
      price_[i] = log_total - logs_.half_more(counts_[i - kReach]);
  }
  const auto price = [&](std::int64_t d) { return price_[static_cast<std::size_t>(d - low_ + kReach)]; };

  from_.resize(2 * steps_.size());
  // The cheapest cost of a plan up to the last step taken, ending at its nearest level (0) or at
  // its other one (1); two scalars, which the compiler keeps in registers.
  const auto first_cost = [&](std::int64_t level) {
    return level > limit || level < -limit ? kInfinite : intra_bits(level, scaler_);
  };
  double best0 = first_cost(options[0].nearest);
  double best1 = has_choice(options[0]) ? first_cost(options[0].other) : kInfinite;
  // Each state keeps the cheaper way in, the first (p = 0) on a tie; a frame without a second
  // choice has no state 1.
  for (std::size_t k = 0; k < steps_.size(); ++k) {
    const std::size_t t = steps_[k];
    const LevelOptions& now = options[t];
    const LevelOptions& before = options[t - 1];
    const double from_nearest_0 = best0 + price(now.nearest - before.nearest);
    const double from_other_0 = best1 + price(now.nearest - before.other);
    const double from_nearest_1 = best0 + price(now.other - before.nearest);
    const double from_other_1 = best1 + price(now.other - before.other);
    const bool via_other_0 = from_other_0 < from_nearest_0;
    const bool via_other_1 = has_choice(now) && from_other_1 < from_nearest_1;
    best0 = via_other_0 ? from_other_0 : from_nearest_0;
    best1 = !has_choice(now) ? kInfinite : via_other_1 ? from_other_1 : from_nearest_1;
    from_[2 * k] = via_other_0;
    from_[2 * k + 1] = via_other_1;
  }
  int s = best1 < best0 ? 1 : 0;
  if ((s == 1 ? best1 : best0) == kInfinite) return false;
  // Back from the last step. A frame before a run of steps that is not itself a step has no
  // choice, or is frame 0; the frames between runs have none: the state going back past them is 0.
  levels[0] = options[0].nearest;
  for (std::size_t k = steps_.size(); k-- > 0;) {
    const std::size_t t = steps_[k];
    levels[t] = level_of(options[t], s);
    s = from_[2 * k + static_cast<std::size_t>(s)];
    if (k == 0 || steps_[k - 1] != t - 1) {
      levels[t - 1] = level_of(options[t - 1], s);
      s = 0;
    }
  }
  return true;
}

}  // namespace fapc::fba

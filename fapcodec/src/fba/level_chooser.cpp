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

}  // namespace

std::int64_t fitted_alphabet(std::int64_t low, std::int64_t high, int range_scaler) {
  return side(std::max<std::int64_t>(high, 0), range_scaler) + side(std::max<std::int64_t>(-low, 0), range_scaler) + 1;
}

void LevelChooser::choose(std::span<const LevelOptions> options, std::int64_t limit, int range_scaler,
                          std::span<std::int64_t> levels) {
  scaler_ = range_scaler;
  // The steps a choice can change: into or out of a frame with two choices. Between two frames
  // without a choice every plan takes the same step, which shifts all costs alike and so decides
  // nothing.
  steps_.clear();
  for (std::size_t t = 0; t < options.size(); ++t) {
    levels[t] = options[t].nearest;
    const bool free = options[t].other != options[t].nearest;
    if (t > 0 && (free || options[t - 1].other != options[t - 1].nearest)) steps_.push_back(t);
  }
  if (steps_.empty()) return;
  double cost = exact_cost(levels);  // leaves the counts of `levels` for the first replan
  trial_.assign(levels.begin(), levels.end());
  for (int round = 0; round < kMaxReplans; ++round) {
    if (!replan(options, limit, trial_)) break;
    const double trial_cost = exact_cost(trial_);  // and those of the trial for the next
    if (!(trial_cost < cost)) break;
    cost = trial_cost;
    std::copy(trial_.begin(), trial_.end(), levels.begin());
  }
}

void LevelChooser::count(std::span<const std::int64_t> levels) {
  std::int64_t low = 0, high = 0;
  for (std::size_t t = 1; t < levels.size(); ++t) {
    low = std::min(low, levels[t] - levels[t - 1]);
    high = std::max(high, levels[t] - levels[t - 1]);
  }
  low_ = low;
  counts_.assign(static_cast<std::size_t>(high - low + 1), 0);
  for (std::size_t t = 1; t < levels.size(); ++t) ++counts_[static_cast<std::size_t>(levels[t] - levels[t - 1] - low)];
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
    if (d > limit || d < -limit) price_[i] = kInfinite;
    else if (i >= kReach && i - kReach < counts_.size()) price_[i] = log_total - logs_.half_more(counts_[i - kReach]);
  }
  const auto price = [&](std::int64_t d) { return price_[static_cast<std::size_t>(d - low_ + kReach)]; };

  const std::size_t n = options.size();
  from_.assign(2 * n, 0);
  double best[2];
  for (int s = 0; s < 2; ++s) {
    const std::int64_t level = level_of(options[0], s);
    best[s] = level > limit || level < -limit ? kInfinite : intra_bits(level, scaler_);
  }
  if (options[0].other == options[0].nearest) best[1] = kInfinite;
  for (const std::size_t t : steps_) {
    double next[2] = {kInfinite, kInfinite};
    for (int s = 0; s < 2; ++s) {
      if (s == 1 && options[t].other == options[t].nearest) continue;
      for (int p = 0; p < 2; ++p) {
        const double c = best[p] + price(level_of(options[t], s) - level_of(options[t - 1], p));
        if (c < next[s]) {
          next[s] = c;
          from_[2 * t + static_cast<std::size_t>(s)] = static_cast<std::uint8_t>(p);
        }
      }
    }
    best[0] = next[0];
    best[1] = next[1];
  }
  int s = best[1] < best[0] ? 1 : 0;
  if (best[s] == kInfinite) return false;
  for (std::size_t t = n; t-- > 0;) {
    levels[t] = level_of(options[t], s);
    s = from_[2 * t + static_cast<std::size_t>(s)];
  }
  return true;
}

}  // namespace fapc::fba

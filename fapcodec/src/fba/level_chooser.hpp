// Chooses the reconstruction of one FAP over one group of planes (docs/fba.md 2, "Quantisation").
// Reconstructions sit on the lattice step * Z, and every lattice point within half a step of the
// value is a correct one: a single point, or two when the value lies exactly half way (even steps
// only, which at fap_quant 1 is every odd value of a FAP with QP 2: a fifth of all values in the
// Xface emotion files). Which of the two is free, so it is chosen to make the group's symbols
// cheap for the decoder's adaptive model.
//
// What a choice costs: the adaptive model starts with every count at 1 and adds 1 per coded
// symbol, so the predictive symbols cost log2((N + A - 1)! / ((A - 1)! prod n_d!)) bits whatever
// their order (N symbols, A the alphabet, n_d how often difference d occurs). Choices only change
// the counts n_d and, through the largest differences, A. The chooser starts from the standard's
// rounding, then re-plans the whole chain with a Viterbi pass that prices each difference at what
// the current counts say it costs, and keeps the new plan while the exact cost falls.
// Private to fapcodec.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace fapc::fba {

struct LevelOptions {
  std::int64_t nearest = 0;  // the standard's rounding: quantise(value, step)
  std::int64_t other = 0;    // the second choice; equal to nearest when there is none
};

// log2(n!) and log2(n + 1/2) for counts up to n, grown on demand: the chooser needs them for every
// count of every chain, and computing the logarithms each time would dominate its work.
class CountLogs {
 public:
  double factorial(std::uint32_t n) { return grow(n), factorial_[n]; }
  double half_more(std::uint32_t n) { return grow(n), half_more_[n]; }

 private:
  void grow(std::uint32_t n) {
    while (factorial_.size() <= n) {
      const auto k = static_cast<double>(factorial_.size());
      factorial_.push_back(factorial_.empty() ? 0.0 : factorial_.back() + std::log2(k));
      half_more_.push_back(std::log2(k + 0.5));
    }
  }
  std::vector<double> factorial_, half_more_;
};

class LevelChooser {
 public:
  // options[t] for the frames of the group (the first one intra); levels receives the choice,
  // every one within +-limit and every difference too. Choices whose difference from the previous
  // level would exceed limit are never taken; the nearest levels must satisfy the limits.
  void choose(std::span<const LevelOptions> options, std::int64_t limit, int range_scaler,
              std::span<std::int64_t> levels);

 private:
  // Counts the differences that no choice changes (steps between two frames without a choice),
  // which lie in [low, high].
  void count_fixed(std::span<const LevelOptions> options, std::int64_t low, std::int64_t high);
  // Counts the differences of `levels` into counts_, low_ and alphabet_: the fixed ones, and
  // those of steps_.
  void count(std::span<const std::int64_t> levels);
  double exact_cost(std::span<const std::int64_t> levels);  // in bits; recounts
  // The cheapest chain under the prices of the last count(); false if none keeps to the limits.
  bool replan(std::span<const LevelOptions> options, std::int64_t limit, std::span<std::int64_t> levels);

  int scaler_ = 1;
  std::int64_t low_ = 0;  // counts_[d - low_] is how often difference d occurs
  std::vector<std::uint32_t> counts_;
  std::int64_t fixed_low_ = 0, fixed_high_ = 0;  // count_fixed's, as low_ and counts_
  std::vector<std::uint32_t> fixed_counts_;
  std::vector<double> price_;        // the bits each difference costs under the current counts
  std::vector<std::uint8_t> from_;   // Viterbi back pointers: 2 per step
  std::vector<std::int64_t> trial_;  // a plan: read and written only at the steps' frames and frame 0
  std::vector<std::size_t> steps_;   // the frames whose step from the previous one can change
  std::int64_t alphabet_ = 1;
  CountLogs logs_;
};

// The predictive alphabet the fitted ranges give differences from `low` to `high`
// (docs/fba-bitstream.md section 5.6: each side a whole number of range steps of 60 / scaler
// quantised units).
std::int64_t fitted_alphabet(std::int64_t low, std::int64_t high, int range_scaler);

}  // namespace fapc::fba

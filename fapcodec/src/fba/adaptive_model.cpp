#include "fba/adaptive_model.hpp"

namespace fapc::fba {

void AdaptiveModel::reset(int symbols) {
  symbols_ = symbols;
  last_ = symbols / 2;
  middle_ = symbols / 2;
  total_ = symbols;
  sums_.assign(round_up(static_cast<std::size_t>(symbols) + 1), 0);
  // cum[j] = n - j: below the middle -j, from it up n - j, then the padding's zeros.
  for (int j = 0; j <= symbols; ++j)
    sums_[static_cast<std::size_t>(j)] = static_cast<std::int16_t>(j <= middle_ ? -j : symbols - j);
}

void AdaptiveModel::rescale() {
  // Halve every frequency (rounding up, so none becomes 0) and rebuild the sums from the top:
  // first cum[j] itself in every entry, then, once the new total is known, the entries up to the
  // middle less that total.
  std::int32_t above = 0;  // the old cum[j + 1]
  for (int j = symbols_ - 1; j >= 0; --j) {
    const auto k = static_cast<std::size_t>(j);
    const std::int32_t old_cum = cum(j);
    const std::int32_t frequency = old_cum - above;
    above = old_cum;
    sums_[k] = static_cast<std::int16_t>(sums_[k + 1] + (frequency + 1) / 2);
  }
  total_ = sums_[0];
  for (int j = 0; j <= middle_; ++j)
    sums_[static_cast<std::size_t>(j)] = static_cast<std::int16_t>(sums_[static_cast<std::size_t>(j)] - total_);
}

}  // namespace fapc::fba

#include "fba/adaptive_model.hpp"

namespace fapc::fba {

void AdaptiveModel::reset(int symbols) {
  symbols_ = symbols;
  last_ = symbols / 2;
  const auto entries = static_cast<std::size_t>(symbols) + 1;
  cum_.assign(round_up(entries), 0);
  for (int j = 0; j < symbols; ++j) cum_[static_cast<std::size_t>(j)] = static_cast<std::int16_t>(symbols - j);
}

void AdaptiveModel::rescale() {
  // Halve every frequency (rounding up, so none becomes 0) and rebuild the sums from the top.
  std::int32_t above = 0;  // the old cum[j + 1]
  for (int j = symbols_ - 1; j >= 0; --j) {
    const auto k = static_cast<std::size_t>(j);
    const std::int32_t frequency = cum_[k] - above;
    above = cum_[k];
    cum_[k] = static_cast<std::int16_t>(cum_[k + 1] + (frequency + 1) / 2);
  }
}

}  // namespace fapc::fba

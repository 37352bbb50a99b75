#include "fba/adaptive_model.hpp"

namespace fapc::fba {

void AdaptiveModel::reset(int symbols) {
  cum_.resize(static_cast<std::size_t>(symbols) + 1);
  for (int j = 0; j <= symbols; ++j) cum_[static_cast<std::size_t>(j)] = static_cast<std::uint16_t>(symbols - j);
}

void AdaptiveModel::rescale() {
  // Halve every frequency (rounding up, so none becomes 0) and rebuild the sums from the top.
  const int n = symbols();
  std::uint16_t above = 0;  // the old cum[j + 1]
  for (int j = n - 1; j >= 0; --j) {
    const auto k = static_cast<std::size_t>(j);
    const int frequency = cum_[k] - above;
    above = cum_[k];
    cum_[k] = static_cast<std::uint16_t>(cum_[k + 1] + (frequency + 1) / 2);
  }
}

}  // namespace fapc::fba

#include "fba/adaptive_model.hpp"

namespace fapc::fba {

void AdaptiveModel::reset(int symbols) {
  symbols_ = symbols;
  last_ = symbols / 2;
  const auto entries = static_cast<std::size_t>(symbols) + 1;
  cum_.resize(round_up(entries));
  // n - j, a vector at a time; 0 from j = n on (the padding).
  constexpr Lanes kLane = {0, 1, 2, 3, 4, 5, 6, 7};
  for (std::size_t j = 0; j < cum_.size(); j += kLanes) {
    const auto first = static_cast<std::int16_t>(symbols - static_cast<int>(j));
    const Lanes lanes = Lanes{first, first, first, first, first, first, first, first} - kLane;
    store(cum_, j, lanes & (lanes > 0));
  }
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

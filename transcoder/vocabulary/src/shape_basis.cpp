#include "fapc/vocabulary/shape_basis.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "fapc/vocabulary/arkit_shapes.hpp"

namespace fapc::vocabulary {
namespace {

// Sweeps of the coordinate descent: each sweep moves every weight to its best value with the
// others held, which never increases the error; the loop ends earlier once no weight moves more
// than kSettled.
constexpr int kMaxSweeps = 200;
constexpr double kSettled = 1e-7;
// A small price on every unit of weight: where two shapes undo each other (eyeLookIn and
// eyeLookOut of one eye, mouthLeft and mouthRight) any pair with the same difference fits, and
// the price picks the one with the least weight, the difference alone (error in shares of the
// legal range, squared: 1e-6 moves a fitted weight by about 1e-5).
constexpr double kWeightPrice = 1e-6;

}  // namespace

ShapeBasis::ShapeBasis(const MappingTable& table, std::vector<std::string> keys) : keys_(std::move(keys)) {
  std::set<int> moved;
  for (int fap = 1; fap <= kFapCount; ++fap) {
    const int legal = fap_table()[static_cast<std::size_t>(fap - 1)].legal_max();
    inverse_scale_squared_[static_cast<std::size_t>(fap - 1)] = legal > 0 ? 1.0 / (double(legal) * legal) : 0.0;
  }
  for (const std::string& key : keys_) {
    std::vector<Entry> column;
    double norm = 0;
    for (const MappingRow& row : table.rows_of(key)) {
      if (row.fap == 0) continue;
      column.push_back({row.fap - 1, row.amount});
      norm += row.amount * row.amount * inverse_scale_squared_[static_cast<std::size_t>(row.fap - 1)];
      moved.insert(row.fap);
    }
    columns_.push_back(std::move(column));
    column_norms_.push_back(norm);
  }
  faps_moved_.assign(moved.begin(), moved.end());
}

FapVector ShapeBasis::to_faps(const std::vector<double>& weights) const {
  FapVector faps{};
  for (std::size_t k = 0; k < columns_.size() && k < weights.size(); ++k) {
    for (const Entry& e : columns_[k]) faps[static_cast<std::size_t>(e.fap_index)] += weights[k] * e.amount;
  }
  return faps;
}

std::vector<double> ShapeBasis::from_faps(const FapVector& faps, const std::vector<double>& start) const {
  std::vector<double> weights = start.size() == keys_.size() ? start : std::vector<double>(keys_.size(), 0.0);
  for (double& w : weights) w = std::clamp(std::isfinite(w) ? w : 0.0, 0.0, 1.0);
  // residual = target - current, on the FAPs the keys move
  FapVector residual{};
  for (int fap : faps_moved_) {
    const auto i = static_cast<std::size_t>(fap - 1);
    residual[i] = std::isfinite(faps[i]) ? faps[i] : 0.0;
  }
  const FapVector current = to_faps(weights);
  for (int fap : faps_moved_) residual[static_cast<std::size_t>(fap - 1)] -= current[static_cast<std::size_t>(fap - 1)];
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    double largest_move = 0;
    for (std::size_t k = 0; k < columns_.size(); ++k) {
      if (column_norms_[k] == 0) continue;
      double dot = 0;
      for (const Entry& e : columns_[k]) {
        const auto i = static_cast<std::size_t>(e.fap_index);
        dot += e.amount * residual[i] * inverse_scale_squared_[i];
      }
      const double updated = std::clamp(weights[k] + (dot - kWeightPrice) / column_norms_[k], 0.0, 1.0);
      const double move = updated - weights[k];
      if (move == 0) continue;
      for (const Entry& e : columns_[k]) residual[static_cast<std::size_t>(e.fap_index)] -= move * e.amount;
      weights[k] = updated;
      largest_move = std::max(largest_move, std::abs(move));
    }
    if (largest_move < kSettled) break;
  }
  return weights;
}

const ShapeBasis& arkit_shape_basis() {
  static const ShapeBasis basis = [] {
    std::vector<std::string> keys;
    for (std::string_view name : arkit_shape_names()) keys.emplace_back(name);
    return ShapeBasis(arkit_table(), std::move(keys));
  }();
  return basis;
}

}  // namespace fapc::vocabulary

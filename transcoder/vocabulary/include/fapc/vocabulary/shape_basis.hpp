// Weights of a set of keys (ARKit shapes, action units) <-> FAP values, through a mapping table.
// Forward, FAPs are the weighted sum of the keys' rows. The inverse, used by the writers, is the
// bounded least-squares fit of the weights (each 0..1) to the FAPs the keys can move, every FAP's
// error measured as a fraction of its legal range, with a tiny price on the total weight to choose
// between equal fits: it comes from the same table, so the two
// directions cannot disagree, and it is exact wherever the keys' rows are independent
// (docs/bridges.md, "The inverse").
#pragma once

#include <array>
#include <string>
#include <vector>

#include "fapc/codec/fap_table.hpp"
#include "fapc/vocabulary/mapping_table.hpp"

namespace fapc::vocabulary {

using FapVector = std::array<double, kFapCount>;  // index 0 is FAP 1 (unused here)

class ShapeBasis {
 public:
  // `keys` in the order the weights use; a key without rows in the table moves nothing.
  ShapeBasis(const MappingTable& table, std::vector<std::string> keys);

  const std::vector<std::string>& keys() const { return keys_; }
  // The FAPs (numbers, ascending) some key moves.
  const std::vector<int>& faps_moved() const { return faps_moved_; }

  FapVector to_faps(const std::vector<double>& weights) const;
  // Weights in 0..1 that best reproduce `faps` on faps_moved(), the least total weight among equal
  // fits. `start` (if its size fits) is where the search begins; the writers start every frame
  // from zero, since a start in a pair of shapes that undo each other would be kept.
  std::vector<double> from_faps(const FapVector& faps, const std::vector<double>& start = {}) const;

 private:
  struct Entry {
    int fap_index;  // 0-based
    double amount;  // FAP units at weight 1
  };
  std::vector<std::string> keys_;
  std::vector<std::vector<Entry>> columns_;  // per key
  std::vector<double> column_norms_;         // per key, sum of (amount / scale)^2
  std::vector<int> faps_moved_;
  FapVector inverse_scale_squared_{};  // 1 / legal_max^2 per FAP
};

// ARKit's 52 shapes, in arkit_shape_names()'s order, over the bundled arkit_faps.tsv; built once.
// The ARKit CSV writer and the 3D head's ARKit targets fit their weights with it.
const ShapeBasis& arkit_shape_basis();

}  // namespace fapc::vocabulary

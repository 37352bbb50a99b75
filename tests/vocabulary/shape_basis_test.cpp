// The inverse the writers use: weights fitted back from FAPs. Checked against the forward table,
// not against numbers of its own.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "fapc/vocabulary/arkit_shapes.hpp"
#include "fapc/vocabulary/shape_basis.hpp"

namespace fapc::vocabulary {
namespace {

std::vector<std::string> arkit_keys() {
  std::vector<std::string> keys;
  for (std::string_view name : arkit_shape_names()) keys.emplace_back(name);
  return keys;
}

// Each shape alone: the fit reproduces its FAPs (its weight may be shared with shapes that move
// the same FAPs the same way, so the FAPs, not the weights, are compared).
TEST(ShapeBasis, EveryShapeAloneComesBack) {
  const ShapeBasis basis(arkit_table(), arkit_keys());
  for (std::size_t k = 0; k < basis.keys().size(); ++k) {
    std::vector<double> weights(basis.keys().size(), 0.0);
    weights[k] = 0.6;
    const FapVector faps = basis.to_faps(weights);
    const FapVector back = basis.to_faps(basis.from_faps(faps));
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const auto i = static_cast<std::size_t>(fap - 1);
      EXPECT_NEAR(back[i], faps[i], 1e-3 * fap_table()[i].legal_max()) << basis.keys()[k] << " FAP " << fap;
    }
  }
}

TEST(ShapeBasis, WeightsStayInRangeAndMovedFapsAreListed) {
  const ShapeBasis basis(arkit_table(), arkit_keys());
  FapVector wild{};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-5000, 5000);
  for (double& v : wild) v = value(random);
  wild[2] = std::nan("");
  for (double w : basis.from_faps(wild)) {
    EXPECT_GE(w, 0.0);
    EXPECT_LE(w, 1.0);
  }
  // ARKit moves no ear (65-68) and no pupil (29, 30); it moves the jaw and head of the eyes.
  const auto& moved = basis.faps_moved();
  for (int fap : {29, 30, 65, 66, 67, 68, 48, 49, 50}) {
    EXPECT_EQ(std::count(moved.begin(), moved.end(), fap), 0) << fap;
  }
  for (int fap : {3, 19, 23, 31, 63}) EXPECT_EQ(std::count(moved.begin(), moved.end(), fap), 1) << fap;
}

TEST(ShapeBasis, OpposedShapesSplitBySign) {
  const ShapeBasis basis(arkit_table(), arkit_keys());
  FapVector faps{};
  faps[23 - 1] = -43633 * 0.5;  // the left eye half-way toward the nose
  const std::vector<double> w = basis.from_faps(faps);
  const auto index = [](const char* name) { return static_cast<std::size_t>(*find_arkit_shape(name)); };
  EXPECT_NEAR(w[index("eyeLookInLeft")], 0.5, 1e-6);
  EXPECT_NEAR(w[index("eyeLookOutLeft")], 0.0, 1e-6);
}

}  // namespace
}  // namespace fapc::vocabulary

#include "fba/shown_values.hpp"

namespace fapc::fba {

namespace {

// Partners are neighbours in the FAP table whose names differ in one letter, l against r.
bool mirrored(int a, int b) {
  const std::string_view x = fap_table()[static_cast<std::size_t>(a - 1)].name;
  const std::string_view y = fap_table()[static_cast<std::size_t>(b - 1)].name;
  if (x.size() != y.size()) return false;
  int differences = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] == y[i]) continue;
    if (!((x[i] == 'l' && y[i] == 'r') || (x[i] == 'r' && y[i] == 'l'))) return false;
    ++differences;
  }
  return differences == 1;
}

std::array<int, kFapCount + 1> partner_table() {
  std::array<int, kFapCount + 1> partners{};
  for (int fap = 3; fap < kFapCount; ++fap)
    if (mirrored(fap, fap + 1)) {
      partners[static_cast<std::size_t>(fap)] = fap + 1;
      partners[static_cast<std::size_t>(fap + 1)] = fap;
    }
  return partners;
}

}  // namespace

int lr_partner(int fap) {
  static const std::array<int, kFapCount + 1> partners = partner_table();
  return fap >= 1 && fap <= kFapCount ? partners[static_cast<std::size_t>(fap)] : 0;
}

}  // namespace fapc::fba

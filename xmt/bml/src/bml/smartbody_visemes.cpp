#include "bml/smartbody_visemes.hpp"

#include <cctype>
#include <charconv>
#include <utility>

#include "fapc/vocabulary/mapping_table.hpp"

namespace fapc::bml {
namespace {

bool same_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// The bundled table, read once. It is fapc's own file, checked by tests/bml/bml_lips_test.cpp
// (every row well formed, every viseme 0..14), so a malformed row is a build defect, skipped here.
const std::vector<std::pair<std::string, int>>& rows() {
  static const std::vector<std::pair<std::string, int>> table = [] {
    std::vector<std::pair<std::string, int>> out;
    for (const std::vector<std::string_view>& cells : vocabulary::bundled_table_cells("smartbody_visemes.tsv")) {
      if (cells.size() != 3) continue;
      int viseme = -1;
      std::from_chars(cells[1].data(), cells[1].data() + cells[1].size(), viseme);
      if (viseme < 0 || viseme > 14) continue;
      out.emplace_back(std::string(cells[0]), viseme);
    }
    return out;
  }();
  return table;
}

}  // namespace

std::optional<int> smartbody_viseme(std::string_view name) {
  for (const auto& [smartbody, viseme] : rows())
    if (same_ignoring_case(smartbody, name)) return viseme;
  return std::nullopt;
}

std::vector<std::string> smartbody_viseme_names() {
  std::vector<std::string> out;
  for (const auto& row : rows()) out.push_back(row.first);
  return out;
}

}  // namespace fapc::bml

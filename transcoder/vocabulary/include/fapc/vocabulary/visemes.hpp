// FAP 1's 15 visemes and the OpenXR / Oculus viseme set (sil, PP, FF, ... ou): one to one, read
// from fapc's own table (data/visemes.tsv, docs/bridges.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::vocabulary {

inline constexpr int kVisemeCount = 15;

struct VisemeRow {
  int viseme = 0;      // FAP 1's viseme_select, 0..14
  std::string mpeg4;   // the standard's name: "none", "PP", ... "ou"
  std::string openxr;  // the lip-sync engines' name: "sil", "PP", ... "ou"
  std::string reason;
  int line = 0;
};

// Reads a viseme table: header `viseme mpeg4 openxr reason`, each of the 15 visemes once, its
// mpeg4 name the standard's, the openxr names distinct. Errors carry line and column.
Result<std::vector<VisemeRow>> parse_viseme_table(std::string_view text, const std::string& file);

// The bundled table, indexed by viseme number.
const std::vector<VisemeRow>& viseme_table();

std::string_view openxr_viseme_name(int viseme);  // 0..14; "" outside
std::optional<int> viseme_from_openxr(std::string_view name);

}  // namespace fapc::vocabulary

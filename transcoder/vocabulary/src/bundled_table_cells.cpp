#include "fapc/vocabulary/mapping_table.hpp"

namespace fapc::vocabulary {

std::vector<std::vector<std::string_view>> bundled_table_cells(std::string_view name) {
  std::vector<std::vector<std::string_view>> rows;
  const std::string_view text = bundled_table_text(name);
  bool header = true;
  for (std::size_t from = 0; from < text.size();) {
    const std::size_t end = std::min(text.find('\n', from), text.size());
    const std::string_view line = text.substr(from, end - from);
    from = end + 1;
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<std::string_view> cells;
    for (std::size_t at = 0, start = 0; at <= line.size(); ++at)
      if (at == line.size() || line[at] == '\t') {
        cells.push_back(line.substr(start, at - start));
        start = at + 1;
      }
    rows.push_back(std::move(cells));
  }
  return rows;
}

}  // namespace fapc::vocabulary

#include "fapc/vocabulary/visemes.hpp"

#include <charconv>
#include <map>

#include "fapc/codec/fap_table.hpp"
#include "fapc/vocabulary/codes.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "tsv_lines.hpp"

namespace fapc::vocabulary {

Result<std::vector<VisemeRow>> parse_viseme_table(std::string_view text, const std::string& file) {
  Result<std::vector<TsvLine>> lines = split_tsv(text, file, kVisemeCount + 1);
  if (!lines) return lines.error();
  if (Status columns = check_columns(*lines, file, {"viseme", "mpeg4", "openxr", "reason"}); !columns) {
    return columns.error();
  }
  std::vector<VisemeRow> rows(kVisemeCount);
  std::map<std::string_view, int> openxr_lines;
  for (std::size_t i = 1; i < lines->size(); ++i) {
    const TsvLine& line = (*lines)[i];
    const TsvCell& number = line.cells[0];
    int viseme = -1;
    const auto [ptr, ec] = std::from_chars(number.text.data(), number.text.data() + number.text.size(), viseme);
    if (ec != std::errc{} || ptr != number.text.data() + number.text.size() || viseme < 0 || viseme >= kVisemeCount) {
      return cell_error(codes::vocabulary::bad_value, file, line, number,
                        "'" + std::string(number.text) + "' is not a viseme number (0-14)");
    }
    VisemeRow& row = rows[static_cast<std::size_t>(viseme)];
    if (row.line != 0) {
      return cell_error(codes::vocabulary::duplicate_row, file, line, number,
                        "viseme " + std::to_string(viseme) + " is already given on line " + std::to_string(row.line));
    }
    if (line.cells[1].text != viseme_name(viseme)) {
      return cell_error(codes::vocabulary::bad_value, file, line, line.cells[1],
                        "viseme " + std::to_string(viseme) + " is '" + std::string(viseme_name(viseme)) +
                            "' in the standard, not '" + std::string(line.cells[1].text) + "'");
    }
    const std::string_view openxr = line.cells[2].text;
    if (openxr.empty())
      return cell_error(codes::vocabulary::empty_cell, file, line, line.cells[2], "the OpenXR name is empty");
    if (const auto [it, fresh] = openxr_lines.emplace(openxr, line.line); !fresh) {
      return cell_error(codes::vocabulary::duplicate_row, file, line, line.cells[2],
                        "'" + std::string(openxr) + "' is already given on line " + std::to_string(it->second));
    }
    if (line.cells[3].text.empty())
      return cell_error(codes::vocabulary::no_reason, file, line, line.cells[3], "the reason is empty");
    row = VisemeRow{viseme, std::string(line.cells[1].text), std::string(openxr), std::string(line.cells[3].text),
                    line.line};
  }
  for (int v = 0; v < kVisemeCount; ++v) {
    if (rows[static_cast<std::size_t>(v)].line == 0) {
      return make_error(codes::vocabulary::missing_row, Location::text(file, lines->front().line, 1),
                        "viseme " + std::to_string(v) + " (" + std::string(viseme_name(v)) + ") has no row",
                        std::string(lines->front().whole));
    }
  }
  return rows;
}

const std::vector<VisemeRow>& viseme_table() {
  // Tested (tests/vocabulary): the bundled file always parses.
  static const std::vector<VisemeRow> table = [] {
    Result<std::vector<VisemeRow>> parsed = parse_viseme_table(bundled_table_text("visemes.tsv"), "visemes.tsv");
    return parsed ? std::move(*parsed) : std::vector<VisemeRow>{};
  }();
  return table;
}

std::string_view openxr_viseme_name(int viseme) {
  const auto& table = viseme_table();
  if (viseme < 0 || static_cast<std::size_t>(viseme) >= table.size()) return {};
  return table[static_cast<std::size_t>(viseme)].openxr;
}

std::optional<int> viseme_from_openxr(std::string_view name) {
  for (const VisemeRow& row : viseme_table()) {
    if (row.openxr == name) return row.viseme;
  }
  return std::nullopt;
}

}  // namespace fapc::vocabulary

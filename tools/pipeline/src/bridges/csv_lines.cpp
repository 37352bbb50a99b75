#include "csv_lines.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "fapc/pipeline/codes.hpp"

namespace fapc::pipeline::bridges {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

bool CsvLines::next(std::vector<CsvCell>& cells) {
  while (position_ < text_.size()) {
    const std::size_t found = text_.find('\n', position_);
    const std::size_t end = found == std::string_view::npos ? text_.size() : found;
    std::string_view line = text_.substr(position_, end - position_);
    position_ = end + 1;
    ++line_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (std::all_of(line.begin(), line.end(), is_blank)) continue;
    whole_ = line;
    cells.clear();
    for (std::size_t start = 0;;) {
      const std::size_t comma = line.find(',', start);
      const std::size_t stop = comma == std::string_view::npos ? line.size() : comma;
      std::size_t first = start, last = stop;
      while (first < last && is_blank(line[first])) ++first;
      while (last > first && is_blank(line[last - 1])) --last;
      cells.push_back({line.substr(first, last - first), static_cast<int>(first) + 1});
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    return true;
  }
  return false;
}

Diagnostic CsvLines::error_at(ErrorCode code, const CsvCell* cell, std::string message) const {
  const int column = cell ? cell->column : static_cast<int>(whole_.size()) + 1;
  return make_error(code, Location::text(file_, line_, column), std::move(message), std::string(whole_));
}

Result<double> CsvLines::number(const CsvCell& cell, std::string_view what) const {
  double value = 0;
  const char* begin = cell.text.data();
  const char* end = begin + cell.text.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars takes no plus sign
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (cell.text.empty() || ec != std::errc{} || ptr != end || !std::isfinite(value)) {
    return error_at(codes::csv::not_a_number, &cell,
                    std::string(what) + ": '" + std::string(cell.text) + "' is not a number");
  }
  return value;
}

Status CsvLines::check_width(const std::vector<CsvCell>& cells, std::size_t width) const {
  if (cells.size() > width) {
    return error_at(codes::csv::cell_count, &cells[width],
                    "more cells than the header's " + std::to_string(width) + " columns");
  }
  if (cells.size() < width) {
    return error_at(codes::csv::cell_count, nullptr,
                    std::to_string(cells.size()) + " cells, but the header has " + std::to_string(width) + " columns");
  }
  return ok_status();
}

Result<std::vector<std::string>> read_header(CsvLines& lines) {
  std::vector<CsvCell> cells;
  if (!lines.next(cells)) {
    return make_error(codes::csv::no_header, Location::text(lines.file(), 1, 1), "an empty CSV file: no header line");
  }
  if (cells.size() > kMaxCsvColumns) {
    return lines.error_at(codes::csv::too_many_columns, &cells[kMaxCsvColumns],
                          "the header has " + std::to_string(cells.size()) + " columns, more than the limit of " +
                              std::to_string(kMaxCsvColumns));
  }
  std::vector<std::string> names;
  names.reserve(cells.size());
  for (const CsvCell& cell : cells) {
    if (cell.text.empty()) return lines.error_at(codes::csv::bad_header, &cell, "an empty column name");
    if (std::find(names.begin(), names.end(), cell.text) != names.end()) {
      return lines.error_at(codes::csv::bad_header, &cell, "column '" + std::string(cell.text) + "' is named twice");
    }
    names.emplace_back(cell.text);
  }
  return names;
}

std::optional<std::size_t> column_of(const std::vector<std::string>& header, std::string_view name) {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) return std::nullopt;
  return static_cast<std::size_t>(it - header.begin());
}

}  // namespace fapc::pipeline::bridges

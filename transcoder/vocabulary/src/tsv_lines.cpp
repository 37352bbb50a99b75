#include "tsv_lines.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "fapc/vocabulary/codes.hpp"

namespace fapc::vocabulary {

Result<std::vector<TsvLine>> split_tsv(std::string_view text, const std::string& file, std::size_t max_lines) {
  // Counted before any line is stored, so a huge file costs one pass and no memory.
  std::size_t rows = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    if (!line.empty() && line.front() != '#' && line != "\r") ++rows;
    pos = end + 1;
  }
  if (rows > max_lines) {
    return make_error(
        codes::vocabulary::too_many_lines, Location::text(file, 1, 1),
        "the table has " + std::to_string(rows) + " lines, more than the limit of " + std::to_string(max_lines));
  }
  std::vector<TsvLine> lines;
  lines.reserve(rows);
  int number = 0;
  for (std::size_t pos = 0; pos <= text.size();) {
    const std::size_t found = text.find('\n', pos);
    const std::size_t end = found == std::string_view::npos ? text.size() : found;
    std::string_view line = text.substr(pos, end - pos);
    ++number;
    pos = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CRLF files read the same
    if (line.empty() || line.front() == '#') {
      if (found == std::string_view::npos) break;
      continue;
    }
    if (const std::size_t cr = line.find('\r'); cr != std::string_view::npos) {
      return make_error(codes::vocabulary::carriage_return, Location::text(file, number, static_cast<int>(cr) + 1),
                        "a carriage return inside a line", std::string(line));
    }
    TsvLine parsed{number, line, {}};
    for (std::size_t start = 0;;) {
      const std::size_t tab = line.find('\t', start);
      const std::size_t stop = tab == std::string_view::npos ? line.size() : tab;
      parsed.cells.push_back({line.substr(start, stop - start), static_cast<int>(start) + 1});
      if (tab == std::string_view::npos) break;
      start = tab + 1;
    }
    lines.push_back(std::move(parsed));
    if (found == std::string_view::npos) break;
  }
  return lines;
}

std::optional<double> finite_number(std::string_view text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc{} || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

Diagnostic cell_error(ErrorCode code, const std::string& file, const TsvLine& line, const TsvCell& cell,
                      std::string message) {
  return make_error(code, Location::text(file, line.line, cell.column), std::move(message), std::string(line.whole));
}

Status check_columns(const std::vector<TsvLine>& lines, const std::string& file,
                     const std::vector<std::string_view>& expected) {
  std::string wanted;
  for (std::string_view name : expected) wanted += (wanted.empty() ? "" : " ") + std::string(name);
  if (lines.empty()) {
    return make_error(codes::vocabulary::bad_header, Location::text(file, 1, 1),
                      "no header line: expected the columns " + wanted);
  }
  const TsvLine& header = lines.front();
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (i >= header.cells.size()) {
      return make_error(codes::vocabulary::bad_header,
                        Location::text(file, header.line, static_cast<int>(header.whole.size()) + 1),
                        "the header ends before column '" + std::string(expected[i]) + "' (expected " + wanted + ")",
                        std::string(header.whole));
    }
    if (header.cells[i].text != expected[i]) {
      return cell_error(codes::vocabulary::bad_header, file, header, header.cells[i],
                        "column " + std::to_string(i + 1) + " is '" + std::string(header.cells[i].text) +
                            "', expected '" + std::string(expected[i]) + "' (the columns are " + wanted + ")");
    }
  }
  for (const TsvLine& line : lines) {
    if (line.cells.size() > expected.size()) {
      return cell_error(codes::vocabulary::cell_count, file, line, line.cells[expected.size()],
                        "more than " + std::to_string(expected.size()) + " tab-separated cells");
    }
    if (line.cells.size() < expected.size()) {
      return make_error(codes::vocabulary::cell_count,
                        Location::text(file, line.line, static_cast<int>(line.whole.size()) + 1),
                        std::to_string(line.cells.size()) + " tab-separated cells, expected " +
                            std::to_string(expected.size()) + " (" + wanted + ")",
                        std::string(line.whole));
    }
  }
  return ok_status();
}

}  // namespace fapc::vocabulary

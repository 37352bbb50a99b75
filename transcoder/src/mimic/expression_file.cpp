#include "fapc/transcoder/expression_file.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "fapc/transcoder/codes.hpp"

namespace fapc {

Result<std::vector<ExpressionEntry>> parse_expression_file(std::string_view text, const std::string& file_name) {
  std::vector<ExpressionEntry> entries;
  int line_number = 0;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
    ++line_number;
    if (line.ends_with('\r')) line.remove_suffix(1);
    std::vector<std::pair<std::string_view, int>> fields;  // text, column
    for (std::size_t i = 0; i < line.size();) {
      if (std::isspace(static_cast<unsigned char>(line[i]))) {
        ++i;
        continue;
      }
      if (line[i] == '#') break;
      const std::size_t start = i;
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])) && line[i] != '#') ++i;
      fields.emplace_back(line.substr(start, i - start), static_cast<int>(start) + 1);
    }
    if (fields.empty()) continue;
    const auto error = [&](ErrorCode code, int column, std::string message) {
      return make_error(code, Location::text(file_name, line_number, column), std::move(message), std::string(line));
    };
    if (fields.size() != 2) {
      return error(codes::expression::field_count, fields.size() > 2 ? fields[2].second : fields[0].second,
                   "expected 'parameter value', found " + std::to_string(fields.size()) + " fields");
    }
    const std::string_view number = fields[1].first;
    double value = 0;
    const auto [stop, status] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (status != std::errc{} || stop != number.data() + number.size() || !std::isfinite(value)) {
      return error(codes::expression::not_a_number, fields[1].second, "'" + std::string(number) + "' is not a number");
    }
    entries.push_back(
        ExpressionEntry{std::string(fields[0].first), value, Location::text(file_name, line_number, fields[0].second)});
  }
  return entries;
}

}  // namespace fapc

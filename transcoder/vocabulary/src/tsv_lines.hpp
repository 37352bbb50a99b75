// The tab-separated lines of a vocabulary table, with the line and column of every cell, so that
// each check can point at what it refuses. Comment ('#') and empty lines are skipped.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::vocabulary {

struct TsvCell {
  std::string_view text;
  int column = 1;  // 1-based byte column
};

struct TsvLine {
  int line = 0;
  std::string_view whole;  // for the caret under an error
  std::vector<TsvCell> cells;
};

// Every non-comment line; an error when there are more than `max_lines` (counted before any is
// stored) or when a line has a carriage return inside it.
Result<std::vector<TsvLine>> split_tsv(std::string_view text, const std::string& file, std::size_t max_lines);

// A finite decimal number filling the whole cell, or nothing.
std::optional<double> finite_number(std::string_view text);

// An error at a cell of a line.
Diagnostic cell_error(ErrorCode code, const std::string& file, const TsvLine& line, const TsvCell& cell,
                      std::string message);

// Checks that `header` names exactly `expected` in order, and that every later line has as many
// cells.
Status check_columns(const std::vector<TsvLine>& lines, const std::string& file,
                     const std::vector<std::string_view>& expected);

}  // namespace fapc::vocabulary

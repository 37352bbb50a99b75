// The lines of the trackers' CSV files, one at a time, with the line and column of every cell:
// comma-separated, with the spaces OpenFace writes after each comma (", " in 2.0, ",  " in some
// 1.x files) taken off, CRLF or LF, with or without a final newline. Nothing is kept but the
// current line, so a file of any size costs the memory of its longest line.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::pipeline::bridges {

// A header wider than this is refused before its names are stored: OpenFace 2.0's widest output
// has 714 columns.
inline constexpr std::size_t kMaxCsvColumns = 4096;

struct CsvCell {
  std::string_view text;  // without the spaces around it
  int column = 1;         // 1-based byte column of its first character
};

class CsvLines {
 public:
  CsvLines(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  // The next line that is not empty, split into `cells`; false at the end of the text.
  bool next(std::vector<CsvCell>& cells);
  int line() const { return line_; }
  std::string_view whole() const { return whole_; }
  const std::string& file() const { return file_; }

  // An error at a cell of the current line, or at its end (cell null).
  Diagnostic error_at(ErrorCode code, const CsvCell* cell, std::string message) const;
  // The cell as a finite number, or an error at it naming `what` (the column).
  Result<double> number(const CsvCell& cell, std::string_view what) const;
  // Cells past the header's width, or missing: an error at the first extra cell or the line end.
  Status check_width(const std::vector<CsvCell>& cells, std::size_t width) const;

 private:
  std::string_view text_;
  std::string file_;
  std::size_t position_ = 0;
  int line_ = 0;
  std::string_view whole_;
};

// The header's cells, checked against kMaxCsvColumns before they are stored; an error for a file
// without any line.
Result<std::vector<std::string>> read_header(CsvLines& lines);

// Column index by name, or nullopt.
std::optional<std::size_t> column_of(const std::vector<std::string>& header, std::string_view name);

}  // namespace fapc::pipeline::bridges

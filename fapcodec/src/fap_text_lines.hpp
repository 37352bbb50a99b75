// Splitting .fap text into physical lines and whitespace-separated tokens with their positions.
// Private to the .fap reader.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fapc::fapfile {

struct Token {
  std::string_view text;
  int column;  // 1-based byte column in the line
};

struct Line {
  int number;             // 1-based physical line number
  std::string_view text;  // without the line end (CR and LF removed)
  std::vector<Token> tokens;
  bool has_tab = false;
  bool trailing_blank = false;
  bool first_is_comment() const { return !tokens.empty() && tokens.front().text[0] == '#'; }
};

// A physical line before tokenizing (tokens are made one line at a time into a reused Line, so
// reading a file does not allocate per line).
struct RawLine {
  int number;
  std::string_view text;
};

struct SplitText {
  std::vector<RawLine> lines;
  bool crlf = false;
  bool final_newline = true;
  bool utf8_bom = false;
};

SplitText split_lines(std::string_view text);
void tokenize(const RawLine& raw, Line& line);

}  // namespace fapc::fapfile

// Splitting .fap text into physical lines and whitespace-separated tokens with their positions.
// Private to the .fap reader.
#pragma once

#include <array>
#include <bitset>
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

// The physical lines of a text, one at a time (a file of millions of lines is never split into a
// list first). What the line ends show is known once every line has been taken.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text);
  // The next line, false at the end of the text.
  bool next(RawLine& line);
  bool crlf() const { return crlf_; }
  bool final_newline() const { return final_newline_; }
  bool utf8_bom() const { return utf8_bom_; }
  std::size_t text_size() const { return text_.size(); }
  const char* text_end() const { return text_.data() + text_.size(); }
  // Bytes of the text before the next line (the BOM included).
  std::size_t offset() const { return next_ + (utf8_bom_ ? 3 : 0); }
  // A cursor at the first line again: the diagnostics made after reading keep only line numbers
  // per frame, and find their lines by walking the text once more.
  LineCursor from_start() const { return LineCursor(text_, utf8_bom_); }

 private:
  LineCursor(std::string_view text, bool utf8_bom) : text_(text), utf8_bom_(utf8_bom) {}
  std::string_view text_;
  std::size_t next_ = 0;
  int number_ = 0;
  bool crlf_ = false;
  bool final_newline_ = true;
  bool utf8_bom_ = false;
};

void tokenize(const RawLine& raw, Line& line);

// A line of nothing but integers, read in one go: the mask and value lines of nearly every file.
struct IntegerLine {
  static constexpr int kMaxTokens = 80;  // a value line has at most 1 + 4 + 6 + 66 tokens
  int count = 0;
  bool has_tab = false;
  bool trailing_blank = false;
  bool bits = true;  // every token is one character, 0 or 1
  std::array<long long, kMaxTokens> values;
};
// False when the line is anything else (empty, a comment, a token that is not '-'? and at most 18
// digits, more than kMaxTokens tokens): the reader then tokenizes it and reads it the general way,
// which gives every diagnostic. `readable_end` (at or after the text's end, in the same buffer):
// when the byte after the text is there and ends its tokens (a line end), the scan stops at it
// instead of checking for the end at every character.
bool scan_integers(std::string_view text, IntegerLine& line, const char* readable_end);
inline bool scan_integers(std::string_view text, IntegerLine& line) {
  return scan_integers(text, line, text.data() + text.size());
}

// The mask line nearly every writer makes: 68 digits 0 or 1 separated by single spaces, perhaps
// followed by spaces (no tab). Sets `mask` (bit i from the i-th digit) and `trailing_blank`;
// false, with nothing changed, for any other line (scan_integers or the general reading takes it).
// Eight bytes at a time: this is half of every .fap file's text.
bool scan_plain_mask(std::string_view text, std::bitset<68>& mask, bool& trailing_blank);

}  // namespace fapc::fapfile

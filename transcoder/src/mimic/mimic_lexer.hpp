// Private: tokens of the Mimic language (Mimic Table 1, docs/mimic.md), with their positions.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::mimic {

enum class TokenKind {
  identifier,
  number,
  string,  // "file.xpr"
  left_brace,
  right_brace,
  left_bracket,
  right_bracket,
  less,
  greater,
  left_paren,
  right_paren,
  semicolon,
  comma,
  equals,
  end_of_input,
  error,  // a lexical error; Lexer::error() says which
};

struct Token {
  TokenKind kind = TokenKind::end_of_input;
  std::string_view text;  // as written, a view into the source (strings without their quotes)
  double number = 0;
  int line = 1;
  int column = 1;

  std::string str() const { return std::string(text); }
};

const char* describe(TokenKind kind);  // "'{'", "a number", ... for messages

// Tokens one at a time (the parser needs one of lookahead, and a million-action program should
// not hold a million tokens): end_of_input at the end, `error` with error() at a lexical error.
class Lexer {
 public:
  Lexer(std::string_view source, const std::string& file_name) : source_(source), file_(file_name) {}

  Token next();
  const Diagnostic& error() const { return error_; }

 private:
  std::string_view source_;
  const std::string& file_;
  std::size_t at_ = 0;
  std::size_t line_start_ = 0;
  int line_ = 1;
  Diagnostic error_;

  int column() const { return static_cast<int>(at_ - line_start_) + 1; }
  Token fail(ErrorCode code, int line, int column, std::string message);
  void advance();
  bool skip_blanks_and_comments();
  bool number_follows() const;
  bool read_number(Token& token);
  bool read_string(Token& token);
};

// The text of line `line` (1-based) of `source`, for carets.
std::string source_line(std::string_view source, int line);

}  // namespace fapc::mimic

// Private: tokens of the Mimic language (Table 1), with their positions.
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
  left_brace, right_brace, left_bracket, right_bracket, less, greater, left_paren, right_paren,
  semicolon, comma, equals,
  end_of_input,
};

struct Token {
  TokenKind kind = TokenKind::end_of_input;
  std::string text;  // as written (strings without their quotes)
  double number = 0;
  int line = 1;
  int column = 1;
};

const char* describe(TokenKind kind);  // "'{'", "a number", ... for messages

// The whole source as tokens, ending with end_of_input; or the first lexical error.
Result<std::vector<Token>> tokenize(std::string_view source, const std::string& file_name);

// The text of line `line` (1-based) of `source`, for carets.
std::string source_line(std::string_view source, int line);

}  // namespace fapc::mimic

#include "mimic_lexer.hpp"

#include <charconv>
#include <string>

#include "fapc/transcoder/codes.hpp"

namespace fapc::mimic {

const char* describe(TokenKind kind) {
  switch (kind) {
    case TokenKind::identifier:
      return "a name";
    case TokenKind::number:
      return "a number";
    case TokenKind::string:
      return "a quoted file name";
    case TokenKind::left_brace:
      return "'{'";
    case TokenKind::right_brace:
      return "'}'";
    case TokenKind::left_bracket:
      return "'['";
    case TokenKind::right_bracket:
      return "']'";
    case TokenKind::less:
      return "'<'";
    case TokenKind::greater:
      return "'>'";
    case TokenKind::left_paren:
      return "'('";
    case TokenKind::right_paren:
      return "')'";
    case TokenKind::semicolon:
      return "';'";
    case TokenKind::comma:
      return "','";
    case TokenKind::equals:
      return "'='";
    case TokenKind::end_of_input:
      return "the end of the program";
    case TokenKind::error:
      return "an error";
  }
  return "?";
}

std::string source_line(std::string_view source, int line) {
  std::size_t start = 0;
  for (int i = 1; i < line && start != std::string_view::npos; ++i) {
    start = source.find('\n', start);
    if (start != std::string_view::npos) ++start;
  }
  if (start == std::string_view::npos || start > source.size()) return {};
  std::string_view text = source.substr(start, source.find('\n', start) - start);
  if (text.ends_with('\r')) text.remove_suffix(1);
  return std::string(text);
}

namespace {

// The "C" locale's classes (fapc never sets another), spelled out: the <cctype> calls are not
// inlined and were a tenth of the lexer's time.
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }  // \t \n \v \f \r
bool starts_identifier(char c) { return is_letter(c) || c == '_'; }
bool continues_identifier(char c) { return is_letter(c) || is_digit(c) || c == '_' || c == '.'; }

TokenKind punctuation(char c) {
  switch (c) {
    case '{':
      return TokenKind::left_brace;
    case '}':
      return TokenKind::right_brace;
    case '[':
      return TokenKind::left_bracket;
    case ']':
      return TokenKind::right_bracket;
    case '<':
      return TokenKind::less;
    case '>':
      return TokenKind::greater;
    case '(':
      return TokenKind::left_paren;
    case ')':
      return TokenKind::right_paren;
    case ';':
      return TokenKind::semicolon;
    case ',':
      return TokenKind::comma;
    case '=':
      return TokenKind::equals;
    default:
      return TokenKind::end_of_input;
  }
}

}  // namespace

Token Lexer::next() {
  if (!skip_blanks_and_comments()) return Token{TokenKind::error, {}, 0, line_, column()};
  Token token;
  token.line = line_;
  token.column = column();
  if (at_ >= source_.size()) return token;
  const char c = source_[at_];
  if (starts_identifier(c)) {
    const std::size_t start = at_;
    while (at_ < source_.size() && continues_identifier(source_[at_])) ++at_;
    token.kind = TokenKind::identifier;
    token.text = source_.substr(start, at_ - start);
  } else if (is_digit(c) || c == '.' || ((c == '-' || c == '+') && number_follows())) {
    if (!read_number(token)) return Token{TokenKind::error, {}, 0, token.line, token.column};
  } else if (c == '"') {
    if (!read_string(token)) return Token{TokenKind::error, {}, 0, token.line, token.column};
  } else if (const TokenKind kind = punctuation(c); kind != TokenKind::end_of_input) {
    token.kind = kind;
    token.text = source_.substr(at_, 1);
    ++at_;
  } else {
    return fail(codes::mimic::unexpected_character, token.line, token.column,
                std::string("unexpected character '") + c + "'");
  }
  return token;
}

Token Lexer::fail(ErrorCode code, int line, int col, std::string message) {
  error_ = make_error(code, Location::text(file_, line, col), std::move(message), source_line(source_, line));
  return Token{TokenKind::error, {}, 0, line, col};
}

void Lexer::advance() {
  if (source_[at_] == '\n') {
    ++line_;
    line_start_ = at_ + 1;
  }
  ++at_;
}

bool Lexer::skip_blanks_and_comments() {
  while (at_ < source_.size()) {
    const char c = source_[at_];
    if (is_space(c)) {
      advance();
    } else if (source_.substr(at_, 2) == "//") {
      while (at_ < source_.size() && source_[at_] != '\n') ++at_;
    } else if (source_.substr(at_, 2) == "/*") {
      const int line = line_;
      const int col = column();
      at_ += 2;
      while (at_ < source_.size() && source_.substr(at_, 2) != "*/") advance();
      if (at_ >= source_.size()) {
        fail(codes::mimic::unterminated, line, col, "unterminated comment: '/*' without '*/'");
        return false;
      }
      at_ += 2;
    } else {
      break;
    }
  }
  return true;
}

bool Lexer::number_follows() const {
  return at_ + 1 < source_.size() && (is_digit(source_[at_ + 1]) || source_[at_ + 1] == '.');
}

bool Lexer::read_number(Token& token) {
  const std::size_t start = at_;
  if (source_[at_] == '-' || source_[at_] == '+') ++at_;
  while (at_ < source_.size() && (is_digit(source_[at_]) || source_[at_] == '.')) ++at_;
  if (at_ < source_.size() && (source_[at_] == 'e' || source_[at_] == 'E')) {
    std::size_t exponent = at_ + 1;
    if (exponent < source_.size() && (source_[exponent] == '-' || source_[exponent] == '+')) ++exponent;
    if (exponent < source_.size() && is_digit(source_[exponent])) {
      at_ = exponent;
      while (at_ < source_.size() && is_digit(source_[at_])) ++at_;
    }
  }
  std::string_view text = source_.substr(start, at_ - start);
  token.text = text;
  if (text.starts_with('+')) text.remove_prefix(1);
  const auto [stop, status] = std::from_chars(text.data(), text.data() + text.size(), token.number);
  if (status != std::errc{} || stop != text.data() + text.size()) {
    fail(codes::mimic::bad_number, token.line, token.column, "'" + token.str() + "' is not a number");
    return false;
  }
  if (at_ < source_.size() && starts_identifier(source_[at_])) {
    fail(codes::mimic::bad_number, line_, column(),
         "a number must not run into a name ('" + token.str() + source_[at_] + "...')");
    return false;
  }
  token.kind = TokenKind::number;
  return true;
}

bool Lexer::read_string(Token& token) {
  ++at_;
  const std::size_t start = at_;
  while (at_ < source_.size() && source_[at_] != '"' && source_[at_] != '\n') ++at_;
  if (at_ >= source_.size() || source_[at_] != '"') {
    fail(codes::mimic::unterminated, token.line, token.column, "unterminated file name: '\"' without a closing '\"'");
    return false;
  }
  token.kind = TokenKind::string;
  token.text = source_.substr(start, at_ - start);
  ++at_;
  return true;
}

}  // namespace fapc::mimic

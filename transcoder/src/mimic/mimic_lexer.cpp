#include "mimic_lexer.hpp"

#include <cctype>
#include <charconv>

namespace fapc::mimic {

const char* describe(TokenKind kind) {
  switch (kind) {
    case TokenKind::identifier: return "a name";
    case TokenKind::number: return "a number";
    case TokenKind::string: return "a quoted file name";
    case TokenKind::left_brace: return "'{'";
    case TokenKind::right_brace: return "'}'";
    case TokenKind::left_bracket: return "'['";
    case TokenKind::right_bracket: return "']'";
    case TokenKind::less: return "'<'";
    case TokenKind::greater: return "'>'";
    case TokenKind::left_paren: return "'('";
    case TokenKind::right_paren: return "')'";
    case TokenKind::semicolon: return "';'";
    case TokenKind::comma: return "','";
    case TokenKind::equals: return "'='";
    case TokenKind::end_of_input: return "the end of the program";
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

bool starts_identifier(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool continues_identifier(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

class Lexer {
 public:
  Lexer(std::string_view source, const std::string& file) : source_(source), file_(file) {}

  Result<std::vector<Token>> run() {
    std::vector<Token> tokens;
    for (;;) {
      if (auto skipped = skip_blanks_and_comments(); !skipped) return skipped.error();
      Token token;
      token.line = line_;
      token.column = column();
      if (at_ >= source_.size()) {
        tokens.push_back(token);
        return tokens;
      }
      const char c = source_[at_];
      if (starts_identifier(c)) {
        const std::size_t start = at_;
        while (at_ < source_.size() && continues_identifier(source_[at_])) ++at_;
        token.kind = TokenKind::identifier;
        token.text = std::string(source_.substr(start, at_ - start));
      } else if (is_digit(c) || c == '.' || ((c == '-' || c == '+') && number_follows())) {
        if (auto number = read_number(token); !number) return number.error();
      } else if (c == '"') {
        if (auto text = read_string(token); !text) return text.error();
      } else if (const TokenKind kind = punctuation(c); kind != TokenKind::end_of_input) {
        token.kind = kind;
        token.text = std::string(1, c);
        ++at_;
      } else {
        return error(token.line, token.column,
                     std::string("unexpected character '") + c + "'");
      }
      tokens.push_back(std::move(token));
    }
  }

 private:
  std::string_view source_;
  const std::string& file_;
  std::size_t at_ = 0;
  std::size_t line_start_ = 0;
  int line_ = 1;

  int column() const { return static_cast<int>(at_ - line_start_) + 1; }

  Diagnostic error(int line, int column, std::string message) const {
    return make_error(Location::text(file_, line, column), std::move(message),
                      source_line(source_, line));
  }

  void advance() {
    if (source_[at_] == '\n') {
      ++line_;
      line_start_ = at_ + 1;
    }
    ++at_;
  }

  Status skip_blanks_and_comments() {
    while (at_ < source_.size()) {
      const char c = source_[at_];
      if (std::isspace(static_cast<unsigned char>(c))) {
        advance();
      } else if (source_.substr(at_, 2) == "//") {
        while (at_ < source_.size() && source_[at_] != '\n') ++at_;
      } else if (source_.substr(at_, 2) == "/*") {
        const int line = line_;
        const int col = column();
        at_ += 2;
        while (at_ < source_.size() && source_.substr(at_, 2) != "*/") advance();
        if (at_ >= source_.size()) return error(line, col, "unterminated comment: '/*' without '*/'");
        at_ += 2;
      } else {
        break;
      }
    }
    return ok_status();
  }

  bool number_follows() const {
    return at_ + 1 < source_.size() && (is_digit(source_[at_ + 1]) || source_[at_ + 1] == '.');
  }

  Status read_number(Token& token) {
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
    token.text = std::string(text);
    if (text.starts_with('+')) text.remove_prefix(1);
    const auto [stop, status] = std::from_chars(text.data(), text.data() + text.size(), token.number);
    if (status != std::errc{} || stop != text.data() + text.size()) {
      return error(token.line, token.column, "'" + token.text + "' is not a number");
    }
    if (at_ < source_.size() && starts_identifier(source_[at_])) {
      return error(line_, column(), "a number must not run into a name ('" + token.text +
                                        source_[at_] + "...')");
    }
    token.kind = TokenKind::number;
    return ok_status();
  }

  Status read_string(Token& token) {
    ++at_;
    const std::size_t start = at_;
    while (at_ < source_.size() && source_[at_] != '"' && source_[at_] != '\n') ++at_;
    if (at_ >= source_.size() || source_[at_] != '"') {
      return error(token.line, token.column, "unterminated file name: '\"' without a closing '\"'");
    }
    token.kind = TokenKind::string;
    token.text = std::string(source_.substr(start, at_ - start));
    ++at_;
    return ok_status();
  }

  static TokenKind punctuation(char c) {
    switch (c) {
      case '{': return TokenKind::left_brace;
      case '}': return TokenKind::right_brace;
      case '[': return TokenKind::left_bracket;
      case ']': return TokenKind::right_bracket;
      case '<': return TokenKind::less;
      case '>': return TokenKind::greater;
      case '(': return TokenKind::left_paren;
      case ')': return TokenKind::right_paren;
      case ';': return TokenKind::semicolon;
      case ',': return TokenKind::comma;
      case '=': return TokenKind::equals;
      default: return TokenKind::end_of_input;
    }
  }
};

}  // namespace

Result<std::vector<Token>> tokenize(std::string_view source, const std::string& file_name) {
  return Lexer(source, file_name).run();
}

}  // namespace fapc::mimic

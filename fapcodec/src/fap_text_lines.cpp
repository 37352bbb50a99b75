#include "fap_text_lines.hpp"

#include <array>
#include <cstring>

namespace fapc::fapfile {

namespace {

// The separators: space, tab, vertical tab and form feed (a table: this test runs once per byte
// of every file read).
constexpr std::array<bool, 256> kBlank = [] {
  std::array<bool, 256> blank{};
  for (const unsigned char c : {' ', '\t', '\v', '\f'}) blank[c] = true;
  return blank;
}();

bool is_blank(char c) { return kBlank[static_cast<unsigned char>(c)]; }

}  // namespace

void tokenize(const RawLine& raw, Line& line) {
  const std::string_view text = raw.text;
  line.number = raw.number;
  line.text = text;
  line.tokens.clear();
  line.has_tab = false;
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  const char* at = begin;
  while (at != end) {
    if (is_blank(*at)) {
      line.has_tab = line.has_tab || *at == '\t';
      ++at;
      continue;
    }
    const char* const start = at;
    while (at != end && !is_blank(*at)) ++at;
    line.tokens.push_back(Token{std::string_view(start, static_cast<std::size_t>(at - start)),
                                static_cast<int>(start - begin) + 1});
  }
  line.trailing_blank = !text.empty() && is_blank(text.back()) && !line.tokens.empty();
}

bool scan_integers(std::string_view text, IntegerLine& line) {
  line.count = 0;
  line.has_tab = false;
  line.bits = true;
  const char* at = text.data();
  const char* const end = at + text.size();
  for (;;) {
    for (; at != end && is_blank(*at); ++at)
      if (*at == '\t') line.has_tab = true;
    if (at == end) break;
    if (line.count == IntegerLine::kMaxTokens) return false;
    const bool negative = *at == '-';
    const char* const digits = at + (negative ? 1 : 0);
    const char* p = digits;
    long long magnitude = 0;
    for (; p != end && p - digits < 18; ++p) {  // 18 digits cannot overflow
      const unsigned digit = static_cast<unsigned char>(*p) - unsigned{'0'};
      if (digit > 9) break;
      magnitude = magnitude * 10 + digit;
    }
    if (p == digits || (p != end && !is_blank(*p))) return false;  // a 19th digit too
    line.bits = line.bits && p - at == 1 && magnitude <= 1;
    line.values[static_cast<std::size_t>(line.count++)] = negative ? -magnitude : magnitude;
    at = p;
  }
  line.trailing_blank = !text.empty() && is_blank(text.back());
  return line.count > 0;
}

LineCursor::LineCursor(std::string_view text) : text_(text) {
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
    utf8_bom_ = true;
    text_.remove_prefix(3);
  }
  final_newline_ = text_.empty() || text_.back() == '\n';
}

bool LineCursor::next(RawLine& line) {
  if (next_ >= text_.size()) return false;
  const char* start = text_.data() + next_;
  const auto* newline = static_cast<const char*>(std::memchr(start, '\n', text_.size() - next_));
  const std::size_t end = newline ? static_cast<std::size_t>(newline - text_.data()) : text_.size();
  std::string_view text = text_.substr(next_, end - next_);
  if (!text.empty() && text.back() == '\r') {
    text.remove_suffix(1);
    crlf_ = true;
  }
  line = RawLine{++number_, text};
  next_ = end + 1;
  return true;
}

}  // namespace fapc::fapfile

#include "fap_text_lines.hpp"

#include <array>
#include <bit>
#include <cstdint>
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
    line.tokens.push_back(
        Token{std::string_view(start, static_cast<std::size_t>(at - start)), static_cast<int>(start - begin) + 1});
  }
  line.trailing_blank = !text.empty() && is_blank(text.back()) && !line.tokens.empty();
}

namespace {

// A character at a time, watching for the end.
bool scan_integers_bounded(std::string_view text, IntegerLine& line) {
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

}  // namespace

bool scan_integers(std::string_view text, IntegerLine& line, const char* readable_end) {
  const char* at = text.data();
  const char* const end = at + text.size();
  // With a byte after the line that is neither a blank nor a digit (its line end), the loops below
  // stop at it by themselves and need not watch for the end; otherwise a character at a time.
  if (readable_end == end || is_blank(*end) || static_cast<unsigned>(static_cast<unsigned char>(*end) - '0') <= 9)
    return scan_integers_bounded(text, line);
  line.count = 0;
  line.has_tab = false;
  line.bits = true;
  int count = 0;
  bool tab = false, bits = true;
  for (;;) {
    for (; is_blank(*at); ++at) tab = tab || *at == '\t';
    if (at == end) break;
    if (count == IntegerLine::kMaxTokens) return false;
    const bool negative = *at == '-';
    const char* const digits = at + (negative ? 1 : 0);
    const char* p = digits;
    unsigned long long magnitude = 0;
    for (unsigned digit; (digit = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9; ++p)
      magnitude = magnitude * 10 + digit;
    // No digit, more than 18 (which could overflow), or something else in the token.
    if (p == digits || p - digits > 18 || (p != end && !is_blank(*p))) return false;
    bits = bits && p - at == 1 && magnitude <= 1;
    const auto value = static_cast<long long>(magnitude);
    line.values[static_cast<std::size_t>(count++)] = negative ? -value : value;
    at = p;
  }
  line.count = count;
  line.has_tab = tab;
  line.bits = bits;
  line.trailing_blank = !text.empty() && is_blank(text.back());
  return count > 0;
}

bool scan_plain_mask(std::string_view text, std::bitset<68>& mask, bool& trailing_blank) {
  constexpr std::size_t kDigits = 68, kLength = 2 * kDigits - 1;           // "d d ... d"
  if constexpr (std::endian::native != std::endian::little) return false;  // the words below are read little-endian
  if (text.size() < kLength) return false;
  for (std::size_t i = kLength; i < text.size(); ++i)
    if (text[i] != ' ') return false;
  // Each 8-byte word holds digits at its even bytes and spaces at its odd ones; a digit byte xor
  // '0' is 0 or 1, which is the FAP's bit.
  constexpr std::uint64_t kSpaces = 0x2000200020002000, kSpaceLanes = 0xFF00FF00FF00FF00;
  constexpr std::uint64_t kZeros = 0x0030003000300030, kBitLanes = 0x0001000100010001;
  const auto four_bits = [](std::uint64_t word, bool& ok) {
    const std::uint64_t digits = (word & ~kSpaceLanes) ^ kZeros;
    ok = ok && (word & kSpaceLanes) == kSpaces && (digits & ~kBitLanes) == 0;
    return (digits | digits >> 15 | digits >> 30 | digits >> 45) & 0xF;
  };
  bool ok = true;
  std::uint64_t low = 0;  // FAPs 1..64
  for (std::size_t w = 0; w < 16; ++w) {
    std::uint64_t word;
    std::memcpy(&word, text.data() + 8 * w, 8);
    low |= four_bits(word, ok) << (4 * w);
  }
  // FAPs 65..68: the last 7 bytes, "d d d d", as a word whose last byte reads as a space.
  std::uint64_t last = 0x2000000000000000;
  std::memcpy(&last, text.data() + 128, 7);
  const std::uint64_t high = four_bits(last, ok);
  if (!ok) return false;
  mask = std::bitset<68>(low);
  for (std::size_t i = 0; i < 4; ++i) mask[64 + i] = (high >> i) & 1;
  trailing_blank = text.size() > kLength;
  return true;
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

#include "fapc/speech/speakable_text.hpp"

#include <algorithm>
#include <cctype>
#include <clocale>
#include <cwctype>

namespace fapc::speech {
namespace {

bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }
bool ascii_punctuation(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u > 0x20 && u < 0x7F && !std::isalnum(u);
}

// The length of the UTF-8 character at s[i] when it is one Unicode assigns (a printable or space
// character of C.UTF-8's classification, which follows Unicode), else 0: a malformed sequence, an
// unassigned code point, a surrogate or a noncharacter.
std::size_t assigned_character(std::string_view s, std::size_t i) {
  static const locale_t utf8 = newlocale(LC_CTYPE_MASK, "C.UTF-8", locale_t{});
  const auto lead = static_cast<unsigned char>(s[i]);
  const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 0;
  if (length == 0 || lead > 0xF4 || i + length > s.size()) return 0;
  char32_t code = lead & (0x7F >> length);
  for (std::size_t k = 1; k < length; ++k) {
    if (!continuation(s[i + k])) return 0;
    code = (code << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
  }
  const char32_t shortest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < shortest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  // Without the C.UTF-8 locale (it is built into glibc since 2.35) every well-formed one passes.
  if (utf8 != locale_t{} && !iswprint_l(static_cast<wint_t>(code), utf8) &&
      !iswspace_l(static_cast<wint_t>(code), utf8))
    return 0;
  return length;
}

// The largest cut <= limit that does not split a UTF-8 character of `s` (from `at`).
std::size_t character_boundary(std::string_view s, std::size_t at, std::size_t limit) {
  std::size_t cut = std::min(s.size(), at + limit);
  while (cut > at + 1 && cut < s.size() && continuation(s[cut])) --cut;
  return cut;
}

}  // namespace

std::string speakable_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  std::size_t word = 0;  // bytes of the word being written
  // A piece of a word (one character), broken off to a new word past kMaxWordBytes.
  const auto append = [&](std::string_view piece) {
    if (word + piece.size() > kMaxWordBytes) {
      out.push_back(' ');
      word = 0;
    }
    out.append(piece);
    word += piece.size();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = ' ';
    if (static_cast<unsigned char>(c) >= 0x80) {
      const std::size_t length = assigned_character(text, i);
      if (length == 0) {
        c = ' ';  // and the rest of a malformed or unassigned character with it
        while (i + 1 < text.size() && continuation(text[i + 1])) ++i;
      } else {
        append(text.substr(i, length));
        i += length - 1;
        continue;
      }
    }
    if (space(c)) {
      if (!out.empty() && out.back() != ' ') out.push_back(' ');
      word = 0;
      continue;
    }
    if (ascii_punctuation(c) && !out.empty() && out.back() == c) {
      // A run of one punctuation mark: one of it ('.' up to an ellipsis of three).
      const bool ellipsis = c == '.' && !(out.size() >= 3 && out[out.size() - 2] == '.' && out[out.size() - 3] == '.');
      if (!ellipsis) continue;
    }
    append(std::string_view(&c, 1));
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::vector<std::string> speakable_pieces(std::string_view text) {
  const std::string shaped = speakable_text(text);
  const std::string_view s = shaped;
  std::vector<std::string> pieces;
  std::size_t at = 0;
  while (at < s.size()) {
    while (at < s.size() && s[at] == ' ') ++at;
    if (at >= s.size()) break;
    std::size_t cut = s.size();
    if (s.size() - at > kMaxPieceBytes) {
      const std::string_view window = s.substr(at, kMaxPieceBytes);
      std::size_t end = std::string_view::npos;
      for (const char* mark : {". ", "! ", "? ", "; ", ", "}) {
        const std::size_t found = window.rfind(mark);
        if (found != std::string_view::npos && found > 0) {
          end = found + 1;
          break;
        }
      }
      if (end == std::string_view::npos) {
        const std::size_t blank = window.rfind(' ');
        end = blank != std::string_view::npos && blank > 0 ? blank : character_boundary(s, at, kMaxPieceBytes) - at;
      }
      cut = at + end;
    }
    pieces.emplace_back(s.substr(at, cut - at));
    at = cut;
  }
  return pieces;
}

}  // namespace fapc::speech

#include "fapc/speech/speakable_text.hpp"

#include <algorithm>
#include <cctype>

namespace fapc::speech {
namespace {

bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }
bool ascii_punctuation(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u > 0x20 && u < 0x7F && !std::isalnum(u);
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
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = ' ';
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
    if (word >= kMaxWordBytes && !continuation(c)) {
      out.push_back(' ');
      word = 0;
    }
    out.push_back(c);
    ++word;
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

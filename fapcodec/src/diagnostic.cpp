#include "fapc/codec/diagnostic.hpp"

#include <algorithm>
#include <string>

namespace fapc {

const char* error_kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::bad_input:
      return "bad_input";
    case ErrorKind::truncated:
      return "truncated";
    case ErrorKind::io:
      return "io";
    case ErrorKind::usage:
      return "usage";
    case ErrorKind::limit_exceeded:
      return "limit_exceeded";
    case ErrorKind::verification_failed:
      return "verification_failed";
    case ErrorKind::unsupported:
      return "unsupported";
  }
  return "bad_input";
}

std::string format_diagnostic(const Diagnostic& d, ShowCode show) {
  std::string out = d.where.file;
  if (d.where.line > 0) {
    out += ':' + std::to_string(d.where.line);
    if (d.where.column > 0) out += ':' + std::to_string(d.where.column);
  } else if (d.where.byte_offset >= 0) {
    out += ": byte " + std::to_string(d.where.byte_offset);
  }
  out += d.severity == Severity::error ? ": error" : ": warning";
  if (show == ShowCode::yes && !d.code.empty()) out += '[' + d.code + ']';
  out += ": ";
  out += d.message;
  return out;
}

namespace {

// The caret line shows a window of the source line, not all of it: a minified or generated input
// can be one line of megabytes, and the terminal (or a log) would get all of it under every error.
// Widths count characters (UTF-8 code points), so a window never cuts a character in two and the
// caret stays under the character the column names (columns themselves count bytes).
constexpr int kShownCharacters = 100;       // at most this many characters of the line
constexpr int kCharactersBeforeCaret = 40;  // of which this many lead up to the caret
constexpr const char* kCut = "...";         // marks a side of the line that is not shown

bool continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// The byte where the character holding byte `at` begins.
std::size_t character_start(const std::string& s, std::size_t at) {
  while (at > 0 && at < s.size() && continuation_byte(s[at])) --at;
  return at;
}

// `at` moved `count` characters back (or forward), stopping at the line's ends.
std::size_t back(const std::string& s, std::size_t at, int count) {
  for (; count > 0 && at > 0; --count) {
    --at;
    while (at > 0 && continuation_byte(s[at])) --at;
  }
  return at;
}
std::size_t forward(const std::string& s, std::size_t at, int count) {
  for (; count > 0 && at < s.size(); --count) {
    ++at;
    while (at < s.size() && continuation_byte(s[at])) ++at;
  }
  return at;
}

}  // namespace

std::string render_with_caret(const Diagnostic& d, ShowCode show) {
  std::string out = format_diagnostic(d, show);
  if (d.source_line.empty() || d.where.column <= 0) return out;
  const std::string& line = d.source_line;
  const auto column_byte = static_cast<std::size_t>(d.where.column - 1);
  const std::size_t caret = character_start(line, std::min(column_byte, line.size()));
  // A column past the line's end (an error at the end of the line) puts the caret after it.
  const std::size_t past_end =
      std::min<std::size_t>(column_byte > line.size() ? column_byte - line.size() : 0, kShownCharacters);
  std::size_t begin = back(line, caret, kCharactersBeforeCaret);
  std::size_t end = forward(line, begin, kShownCharacters);
  if (end == line.size()) begin = std::min(begin, back(line, end, kShownCharacters));
  out += '\n';
  if (begin > 0) out += kCut;
  out.append(line, begin, end - begin);
  if (end < line.size()) out += kCut;
  out += '\n';
  if (begin > 0) out.append(std::char_traits<char>::length(kCut), ' ');
  // Tabs in the source line are kept under the caret so it lines up in a terminal.
  for (std::size_t at = begin; at < caret; at = forward(line, at, 1)) out += line[at] == '\t' ? '\t' : ' ';
  out.append(past_end, ' ');
  out += '^';
  return out;
}

}  // namespace fapc

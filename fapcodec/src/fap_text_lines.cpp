#include "fap_text_lines.hpp"

namespace fapc::fapfile {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

}  // namespace

void tokenize(const RawLine& raw, Line& line) {
  const std::string_view text = raw.text;
  line.number = raw.number;
  line.text = text;
  line.tokens.clear();
  line.has_tab = false;
  std::size_t i = 0;
  while (i < text.size()) {
    if (is_blank(text[i])) {
      if (text[i] == '\t') line.has_tab = true;
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < text.size() && !is_blank(text[i])) ++i;
    line.tokens.push_back(Token{text.substr(start, i - start), static_cast<int>(start) + 1});
  }
  line.trailing_blank = !text.empty() && is_blank(text.back()) && !line.tokens.empty();
}

SplitText split_lines(std::string_view text) {
  SplitText out;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") {
    out.utf8_bom = true;
    text.remove_prefix(3);
  }
  out.final_newline = text.empty() || text.back() == '\n';
  int number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') {
      line.remove_suffix(1);
      out.crlf = true;
    }
    out.lines.push_back(RawLine{++number, line});
    start = end + 1;
  }
  return out;
}

}  // namespace fapc::fapfile

// The family readers of fap_family_checkers.hpp. Each rule cites the program behaviour it comes
// from (docs/fap-files.md section 3).
#include "fap_family_checkers.hpp"

#include <cctype>
#include <cstdlib>

namespace fapc::test {

namespace {

// Lines split on '\n' only; a CR is kept and then refused (fapc writes LF, which every family
// reads; VREng's reading of CR is not established).
std::vector<std::string> lines_of(const std::string& text, std::string& error) {
  std::vector<std::string> lines;
  if (text.empty() || text.back() != '\n') error = "no newline at the end of the file";
  std::string line;
  for (const char c : text) {
    if (c == '\n') {
      lines.push_back(line);
      line.clear();
    } else {
      line += c;
    }
  }
  if (!line.empty()) lines.push_back(line);
  for (const std::string& l : lines)
    if (l.find('\r') != std::string::npos) error = "a CR in a line";
  return lines;
}

// Tokens between single spaces, with at most one space at the end (the form every family
// writes): a tab, a doubled or leading space is refused.
std::optional<std::vector<std::string>> single_spaced(const std::string& line, bool trailing_space) {
  if (line.find('\t') != std::string::npos || line.find("  ") != std::string::npos || line.empty() ||
      line.front() == ' ')
    return std::nullopt;
  if (trailing_space != (line.back() == ' ')) return std::nullopt;
  std::vector<std::string> tokens;
  std::size_t at = 0;
  while (at < line.size()) {
    const std::size_t space = line.find(' ', at);
    const std::size_t end = space == std::string::npos ? line.size() : space;
    tokens.push_back(line.substr(at, end - at));
    at = end + 1;
  }
  return tokens;
}

// A decimal integer as `%d`, Integer.parseInt and atof all read alike: optional '-', digits.
std::optional<long long> integer(const std::string& token) {
  if (token.empty()) return std::nullopt;
  std::size_t i = token[0] == '-' ? 1 : 0;
  if (i == token.size()) return std::nullopt;
  for (std::size_t k = i; k < token.size(); ++k)
    if (!std::isdigit(static_cast<unsigned char>(token[k]))) return std::nullopt;
  return std::strtoll(token.c_str(), nullptr, 10);
}

struct Form {
  bool header;               // `2.1 <name> <fps> <n>`
  std::size_t mask_tokens;   // 68, or 69 with the last 0
  bool single_fap12;         // FAP 1 and FAP 2 one value each
  bool millisecond_numbers;  // SEMAINE: a leading time line, then stamps on one step
};

Form form_of(Family family) {
  switch (family) {
    case Family::greta_java:
      return {true, 69, true, false};  // 3.3: its writer's 69 slots; one value for FAP 1/2
    case Family::vreng:
      return {true, 68, true, false};  // 3.6: at most 68 mask bits; plain single values
    case Family::semaine:
      return {false, 68, true, true};  // 3.5 and ReadFapBuffer (3.4): one value each
    default:
      return {true, 68, false, false};  // 3.1, 3.4 ReadFapFile, 5: 4 and 6 fields
  }
}

// The header as each family reads it. Xface: `>>` into version (float), name (char[255]), fps
// (float, truncated), count. Greta C++: `%f %s %d %d`: one-token name, integer fps. Greta Java:
// one line, ignored, as its writer puts it (no trailing space). VREng: the first token "2.0" or
// "2.1", the count the last token. The safe form: a name below 128 characters (the reference
// coder's buffer), integer fps, the exact count.
std::string check_header(const std::string& line, Seen& seen, long long& count) {
  const auto tokens = single_spaced(line, false);
  if (!tokens || tokens->size() != 4) return "the header is not four single-spaced tokens without a trailing space";
  if ((*tokens)[0] != "2.1") return "the version is not 2.1";
  if ((*tokens)[1].size() >= 128) return "the header name is 128 characters or more";
  const auto fps = integer((*tokens)[2]);
  const auto n = integer((*tokens)[3]);
  if (!fps || *fps <= 0 || !n || *n < 0) return "fps or frame count is not a positive integer";
  seen.fps = static_cast<int>(*fps);
  count = *n;
  return {};
}

// One mask/value pair; `numbers` are checked by the caller.
std::string read_pair(const std::string& mask_line, const std::string& value_line, const Form& form, SeenFrame& frame) {
  // Every family writes, and VREng needs, single spaces with the trailing one real files have.
  const auto mask = single_spaced(mask_line, true);
  if (!mask || mask->size() != form.mask_tokens)
    return "a mask line is not " + std::to_string(form.mask_tokens) + " single-spaced tokens and a space";
  for (std::size_t i = 0; i < mask->size(); ++i) {
    if ((*mask)[i] != "0" && (*mask)[i] != "1") return "a mask token is not 0 or 1";
    if (i < 68)
      frame.mask.set(i, (*mask)[i] == "1");
    else if ((*mask)[i] != "0")
      return "the 69th mask token is not 0";
  }
  const auto values = single_spaced(value_line, true);
  if (!values) return "a value line is not single-spaced tokens and a space";
  std::vector<long long> numbers;
  for (const std::string& token : *values) {
    const auto v = integer(token);  // Greta (both) reads integers only; Java cuts the file at a float
    if (!v) return "a value is not an integer: '" + token + "'";
    numbers.push_back(*v);
  }
  const std::size_t fap1 = frame.mask.test(0) ? (form.single_fap12 ? 1 : 4) : 0;
  const std::size_t fap2 = frame.mask.test(1) ? (form.single_fap12 ? 1 : 6) : 0;
  const std::size_t low = frame.mask.count() - frame.mask.test(0) - frame.mask.test(1);
  if (numbers.size() != 1 + fap1 + fap2 + low) return "a value line has the wrong number of values for its mask";
  std::size_t at = 0;
  frame.number = numbers[at++];
  frame.fap1.assign(numbers.begin() + static_cast<long>(at), numbers.begin() + static_cast<long>(at + fap1));
  at += fap1;
  frame.fap2.assign(numbers.begin() + static_cast<long>(at), numbers.begin() + static_cast<long>(at + fap2));
  at += fap2;
  frame.values.assign(numbers.begin() + static_cast<long>(at), numbers.end());
  if (fap1 == 4 && (frame.fap1[0] < 0 || frame.fap1[0] > 14 || frame.fap1[2] < 0 || frame.fap1[2] > 63))
    return "a viseme field is out of range";
  return {};
}

}  // namespace

Seen read_as(Family family, const std::string& text) {
  Seen seen;
  const Form form = form_of(family);
  const auto lines = lines_of(text, seen.error);
  if (!seen.error.empty()) return seen;
  std::size_t at = 0;
  long long count = -1;
  long long first_stamp = 0;
  if (form.header) {
    if (lines.empty()) return seen.error = "no header", seen;
    seen.error = check_header(lines[at++], seen, count);
  } else {
    // SEMAINE 2008: a bare time first; the stamps follow one frame later (3.5).
    const auto time = lines.empty() ? std::nullopt : integer(lines[0]);
    if (!time) return seen.error = "no leading time line", seen;
    first_stamp = *time;
    ++at;
  }
  if (!seen.error.empty()) return seen;
  // Greta Java takes lines strictly in pairs after its one header line, Greta C++ reads exactly
  // `count` frames, Xface indexes rows by frame number: no blank or comment line anywhere.
  if ((lines.size() - at) % 2 != 0) return seen.error = "lines do not pair up as mask and value", seen;
  for (; at < lines.size(); at += 2) {
    SeenFrame frame;
    if (auto e = read_pair(lines[at], lines[at + 1], form, frame); !e.empty()) return seen.error = e, seen;
    seen.frames.push_back(frame);
  }
  const auto n = static_cast<long long>(seen.frames.size());
  if (form.header && count != n) return seen.error = "the header count is not the number of frames", seen;
  for (long long k = 0; k < n; ++k) {
    const long long number = seen.frames[static_cast<std::size_t>(k)].number;
    if (form.millisecond_numbers) {
      // Stamps on one step from the time line: 40 ms at Greta's 25 fps.
      const long long step = n > 0 ? seen.frames[0].number - first_stamp : 0;
      if (step <= 0 || 1000 % step != 0 || number != first_stamp + (k + 1) * step)
        return seen.error = "frame stamps are not on one millisecond step after the time line", seen;
      seen.fps = static_cast<int>(1000 / step);
    } else if (number != k) {
      // Xface: the row index, below the count; the safe form: 0..n-1 in order.
      return seen.error = "frame numbers are not 0..n-1 in order", seen;
    }
  }
  return seen;
}

}  // namespace fapc::test

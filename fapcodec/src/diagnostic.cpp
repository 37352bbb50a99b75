#include "fapc/codec/diagnostic.hpp"

namespace fapc {

const char* error_kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::bad_input: return "bad_input";
    case ErrorKind::truncated: return "truncated";
    case ErrorKind::io: return "io";
    case ErrorKind::usage: return "usage";
    case ErrorKind::limit_exceeded: return "limit_exceeded";
    case ErrorKind::verification_failed: return "verification_failed";
    case ErrorKind::unsupported: return "unsupported";
  }
  return "bad_input";
}

std::string format_diagnostic(const Diagnostic& d) {
  std::string out = d.where.file;
  if (d.where.line > 0) {
    out += ':' + std::to_string(d.where.line);
    if (d.where.column > 0) out += ':' + std::to_string(d.where.column);
  } else if (d.where.byte_offset >= 0) {
    out += ": byte " + std::to_string(d.where.byte_offset);
  }
  out += d.severity == Severity::error ? ": error: " : ": warning: ";
  out += d.message;
  return out;
}

std::string render_with_caret(const Diagnostic& d) {
  std::string out = format_diagnostic(d);
  if (d.source_line.empty() || d.where.column <= 0) return out;
  out += '\n';
  out += d.source_line;
  out += '\n';
  // Tabs in the source line are kept under the caret so it lines up in a terminal.
  for (int i = 0; i + 1 < d.where.column; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out += (k < d.source_line.size() && d.source_line[k] == '\t') ? '\t' : ' ';
  }
  out += '^';
  return out;
}

}  // namespace fapc

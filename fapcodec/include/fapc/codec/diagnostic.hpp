// Errors and warnings as values. The libraries never print or exit: they return a Diagnostic and
// the command line decides how to show it (see docs/cli.md).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "fapc/codec/file_name.hpp"

namespace fapc {

enum class Severity { warning, error };

// Where a diagnostic points. Text inputs use line and column (1-based); binary inputs use a byte
// offset. A line of 0 and an offset of -1 mean "the whole file".
struct Location {
  FileName file;
  int line = 0;
  int column = 0;
  std::int64_t byte_offset = -1;

  static Location text(std::string file, int line, int column) { return Location{std::move(file), line, column, -1}; }
  static Location binary(std::string file, std::int64_t offset) { return Location{std::move(file), 0, 0, offset}; }
  static Location whole_file(std::string file) { return Location{std::move(file), 0, 0, -1}; }
};

// What went wrong, as a value callers decide by (the exit status, whether to retry, whether a
// stream merely ends early). Behaviour never depends on a message's wording: only on this.
enum class ErrorKind {
  bad_input,            // the input breaks its format's rules (the default)
  truncated,            // the input ends before its syntax does (a special case of bad input)
  io,                   // a file cannot be opened, read or written
  usage,                // the caller asked for something impossible (options, paths)
  limit_exceeded,       // a resource limit (frames, depth, size...) would be passed
  verification_failed,  // an output does not read back as it should
  unsupported,          // valid input that fapc does not implement
};

// The stable lower-case name of a kind ("limit_exceeded"), for JSON and tests.
const char* error_kind_name(ErrorKind kind);

struct Diagnostic {
  Severity severity = Severity::error;
  Location where;
  std::string message;
  // The source line the diagnostic points into, when there is one, so a caret can be drawn.
  std::string source_line;
  ErrorKind kind = ErrorKind::bad_input;  // meaningful for errors; warnings keep the default
  // What went wrong, as a stable dotted name ("fba.truncated", "mimic.out_of_range"): every
  // error has one (make_error takes it); the command line counts repeated warnings by it (never by
  // their wording). A warning made without a code has none.
  std::string code{};
};

// An error's code and the kind of failure it is. Written only in a library's code table
// (fapc/<library>/codes.def, listed in docs/errors.md), where a constant codes::fba::truncated
// is declared for the code "fba.truncated": make_error takes one, so every error has a code
// that the table knows.
struct ErrorCode {
  const char* name;
  ErrorKind kind;
};

// A warning's code, a type of its own so that it cannot be mistaken for a message. Declared in the
// same tables as the errors' codes.
struct WarningCode {
  const char* name;
};

using Diagnostics = std::vector<Diagnostic>;

// Whether the diagnostic's code is written after its severity ("error[fba.truncated]: ").
enum class ShowCode { no, yes };

// "FILE:LINE:COL: error: MESSAGE" or "FILE: byte N: error: MESSAGE" (docs/cli.md). Without the
// caret lines; see render_with_caret for the full form.
std::string format_diagnostic(const Diagnostic& d, ShowCode show = ShowCode::no);

// format_diagnostic plus, when the source line is known, the line (at most 100 characters of it
// around the column, "..." marking a cut side) and a caret under the column.
std::string render_with_caret(const Diagnostic& d, ShowCode show = ShowCode::no);

// Built field by field: Diagnostic grows fields (code) that most diagnostics leave empty.
inline Diagnostic make_diagnostic(Severity severity, ErrorKind kind, Location where, std::string message,
                                  std::string source_line, const char* code) {
  Diagnostic d;
  d.severity = severity;
  d.where = std::move(where);
  d.message = std::move(message);
  d.source_line = std::move(source_line);
  d.kind = kind;
  d.code = code;
  return d;
}
inline Diagnostic make_error(ErrorCode code, Location where, std::string message, std::string source_line = {}) {
  return make_diagnostic(Severity::error, code.kind, std::move(where), std::move(message), std::move(source_line),
                         code.name);
}
// `inner` told again at another place or in other words: its code and kind stay, the failure being
// the same (an operand's error shown where the expression names it).
inline Diagnostic retold(const Diagnostic& inner, Location where, std::string message, std::string source_line = {}) {
  Diagnostic d = inner;
  d.where = std::move(where);
  d.message = std::move(message);
  d.source_line = std::move(source_line);
  return d;
}
// A warning without a code is always shown (never counted with others).
inline Diagnostic make_warning(Location where, std::string message, std::string source_line = {}) {
  return make_diagnostic(Severity::warning, ErrorKind::bad_input, std::move(where), std::move(message),
                         std::move(source_line), "");
}
inline Diagnostic make_warning(WarningCode code, Location where, std::string message, std::string source_line = {}) {
  return make_diagnostic(Severity::warning, ErrorKind::bad_input, std::move(where), std::move(message),
                         std::move(source_line), code.name);
}

// A value or the error that prevented it. Warnings travel beside the value where a reader
// produces them (see each reader's result type).
template <class T>
class Result {
 public:
  Result(T value) : state_(std::move(value)) {}           // NOLINT: implicit on purpose
  Result(Diagnostic error) : state_(std::move(error)) {}  // NOLINT: implicit on purpose

  bool ok() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return ok(); }
  T& value() { return std::get<T>(state_); }
  const T& value() const { return std::get<T>(state_); }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const Diagnostic& error() const { return std::get<Diagnostic>(state_); }

 private:
  std::variant<T, Diagnostic> state_;
};

// For operations that produce nothing but can fail.
struct Unit {};
using Status = Result<Unit>;
inline Status ok_status() { return Unit{}; }

}  // namespace fapc

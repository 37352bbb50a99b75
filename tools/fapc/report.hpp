// How the program shows diagnostics: one per line on standard error, with the source line and a
// caret where there is one (docs/cli.md). -q shows errors only; -v also says what is read and
// written. Warnings of one code (Diagnostic::code) are shown kMaxShownPerCode times, then counted:
// the count comes at the end of the run, "fapc: ... and 6,509 more like this (CODE)". Grouping is
// by the code, never by the wording; a warning without a code is always shown.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::cli {

enum class Verbosity { quiet, normal, verbose };
void set_verbosity(Verbosity level);
Verbosity verbosity();

inline constexpr int kMaxShownPerCode = 5;

void report(const Diagnostic& d);
void report_all(const Diagnostics& ds);

// Prints the warnings, then the error if any; returns the exit status (0 without an error).
int report_outcome(const Diagnostics& warnings, const std::optional<Diagnostic>& error);

// Diagnostics about the file `path` name it `shown` instead (the copy of standard input: "-").
void show_file_as(const std::string& path, const std::string& shown);

// With -v only: "fapc: MESSAGE" on standard error.
void tell(const std::string& message);

// The counts of warnings not shown, one line per code; call once, at the end of the run.
void finish_reports();

// 6509 as "6,509".
std::string with_thousands(std::int64_t n);

}  // namespace fapc::cli

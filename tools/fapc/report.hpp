// How the program shows diagnostics: one per line on standard error, with the source line and a
// caret where there is one (docs/cli.md).
#pragma once

#include <optional>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::cli {

void report(const Diagnostic& d);
void report_all(const Diagnostics& ds);

// Prints the warnings, then the error if any; returns the exit status (0 without an error).
int report_outcome(const Diagnostics& warnings, const std::optional<Diagnostic>& error);

}  // namespace fapc::cli

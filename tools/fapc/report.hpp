// How the program shows diagnostics: one per line on standard error, with the source line and a
// caret where there is one (docs/cli.md).
#pragma once

#include "fapc/codec/diagnostic.hpp"

namespace fapc::cli {

void report(const Diagnostic& d);
void report_all(const Diagnostics& ds);

}  // namespace fapc::cli

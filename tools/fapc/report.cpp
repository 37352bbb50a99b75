#include "fapc/report.hpp"

#include <iostream>

#include "fapc/commands.hpp"

namespace fapc::cli {

void report(const Diagnostic& d) { std::cerr << render_with_caret(d) << '\n'; }

void report_all(const Diagnostics& ds) {
  for (const Diagnostic& d : ds) report(d);
}

int report_outcome(const Diagnostics& warnings, const std::optional<Diagnostic>& error) {
  report_all(warnings);
  if (!error) return kExitOk;
  report(*error);
  return exit_status(error->kind);
}

}  // namespace fapc::cli

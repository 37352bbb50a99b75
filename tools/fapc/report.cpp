#include "fapc/report.hpp"

#include <iostream>

namespace fapc::cli {

void report(const Diagnostic& d) { std::cerr << render_with_caret(d) << '\n'; }

void report_all(const Diagnostics& ds) {
  for (const Diagnostic& d : ds) report(d);
}

}  // namespace fapc::cli

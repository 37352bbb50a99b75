#include "fapc/report.hpp"

#include <iostream>
#include <map>
#include <mutex>

#include "fapc/commands.hpp"

namespace fapc::cli {

namespace {

Verbosity level = Verbosity::normal;
std::mutex reporting;  // batch reports from its workers (one at a time, but not the main thread)
std::map<std::string, std::int64_t> seen_per_code;
std::map<std::string, std::string> shown_names;

}  // namespace

void set_verbosity(Verbosity l) { level = l; }
Verbosity verbosity() { return level; }

std::string with_thousands(std::int64_t n) {
  std::string digits = std::to_string(n < 0 ? -n : n);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(static_cast<std::size_t>(at), ",");
  return (n < 0 ? "-" : "") + digits;
}

void report(const Diagnostic& d) {
  const std::lock_guard lock(reporting);
  if (d.severity == Severity::warning) {
    if (level == Verbosity::quiet) return;
    // -v shows every warning; otherwise the first few of each code.
    if (!d.code.empty() && ++seen_per_code[d.code] > kMaxShownPerCode && level != Verbosity::verbose) return;
  }
  // -v names each diagnostic's code ("error[fba.truncated]: "), as docs/errors.md lists them.
  const ShowCode show = level == Verbosity::verbose ? ShowCode::yes : ShowCode::no;
  if (const auto alias = shown_names.find(d.where.file); alias != shown_names.end()) {
    Diagnostic renamed = d;
    renamed.where.file = alias->second;
    std::cerr << render_with_caret(renamed, show) << '\n';
    return;
  }
  std::cerr << render_with_caret(d, show) << '\n';
}

void show_file_as(const std::string& path, const std::string& shown) {
  const std::lock_guard lock(reporting);
  shown_names[path] = shown;
}

void report_all(const Diagnostics& ds) {
  for (const Diagnostic& d : ds) report(d);
}

int report_outcome(const Diagnostics& warnings, const std::optional<Diagnostic>& error) {
  report_all(warnings);
  if (!error) return kExitOk;
  report(*error);
  return exit_status(error->kind);
}

void tell(const std::string& message) {
  if (level != Verbosity::verbose) return;
  const std::lock_guard lock(reporting);
  std::cerr << "fapc: " << message << '\n';
}

void finish_reports() {
  const std::lock_guard lock(reporting);
  if (level != Verbosity::normal) return;
  for (const auto& [code, seen] : seen_per_code)
    if (seen > kMaxShownPerCode)
      std::cerr << "fapc: ... and " << with_thousands(seen - kMaxShownPerCode) << " more like this (" << code
                << "; -v shows them all)\n";
  seen_per_code.clear();
}

}  // namespace fapc::cli

// fapc validate FILE...: checks XML documents against the project's schemas (the root element
// picks the schema; see xmt/src/schema_registry.cpp). Problems go to standard error with line and
// column; a valid file gets one line on standard output. Exit 1 when any file has an error.
#include <iostream>

#include "fapc/args.hpp"
#include "fapc/commands.hpp"
#include "fapc/pipeline/validate.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

bool validate_one(const std::string& path, const std::string& named) {
  auto checked = pipeline::validate(path);
  if (!checked) {
    report(checked.error());
    return false;
  }
  report_all(checked->problems);
  if (!checked->valid()) return false;
  std::cout << named << ": valid " << checked->kind << " (" << checked->schema << ")\n";
  return true;
}

int run_validate(const std::vector<std::string>& argv) {
  Args args("validate", argv);
  if (!args.ok()) return usage_error("validate", args);
  if (args.positionals().empty()) return usage_error("validate", codes::cli::operands, "expected at least one FILE");
  bool all_valid = true;
  StandardInputCopy copy;
  for (const std::string& path : args.positionals()) {
    // The root element picks the schema, so standard input needs no --from here.
    std::string input = path == "-" ? copy.path() : path;
    if (path == "-") show_file_as(input, "-");
    all_valid = validate_one(input, path) && all_valid;
  }
  return all_valid ? kExitOk : kExitBadInput;
}

const RegisterCommand validate_command{"validate", run_validate};

}  // namespace

}  // namespace fapc::cli

// Every library's table of diagnostic codes, in the order of the layers (codec first): what
// docs/errors.md lists and what the tests check for unique, well-formed codes.
#pragma once

#include <span>
#include <vector>

#include "fapc/codec/code_table.hpp"

namespace fapc::pipeline {

struct CodeTable {
  const char* library;  // its target: "fapc::codec", "fapc::mpeg4", ...
  std::span<const CodeRow> rows;
};

// The libraries' tables (the command line's own is in tools/fapc/cli_codes.def).
std::vector<CodeTable> code_tables();

}  // namespace fapc::pipeline

// `.xpr` expression files (docs/mimic.md, "Timing and values", defxpr): a facial expression as
// `parameter value` lines, `#` comments. Parameters are FAP names or numbers, or names a profile
// maps.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc {

struct ExpressionEntry {
  std::string parameter;
  double value = 0;
  Location where;  // of the parameter name
};

// Syntax only (two fields per line, a finite number); errors at file:line:col. Whether the names
// exist is the caller's question (it knows the profile).
Result<std::vector<ExpressionEntry>> parse_expression_file(std::string_view text, const std::string& file_name);

}  // namespace fapc

// Private: recursive descent over the grammar of Mimic Table 1 (docs/mimic.md, "Grammar").
#pragma once

#include <string>
#include <string_view>

#include "fapc/codec/diagnostic.hpp"
#include "mimic_ast.hpp"

namespace fapc::mimic {

Result<Program> parse_program(std::string_view source, const std::string& file_name);

}  // namespace fapc::mimic

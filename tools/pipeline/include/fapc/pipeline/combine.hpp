// The Algebra of Expressions over files (docs/algebra.md): `fapc combine` and `.combine` inputs.
#pragma once

#include <string>

#include "fapc/pipeline/options.hpp"
#include "fapc/transcoder/algebra_expression.hpp"

namespace fapc::pipeline {

// Operands are loaded with load() (any registered input) or, for .xpr, as facial states.
// In a .combine file (`including_file`) they are includes: names relative to its folder, under
// the include policy of options.includes, cycles refused. Empty `including_file`: the expression
// comes from the command line and its operands are inputs like any other. Warnings of the
// operands are appended to `warnings`.
Result<algebra::Value> evaluate_combination(const std::string& expression, const std::string& including_file,
                                            const ConvertOptions& options, Diagnostics& warnings);

// The result as frames at `fps` (a state is one frame), named `name`.
FapSequence frames_of(const algebra::Value& value, int fps, const std::string& name);

}  // namespace fapc::pipeline

// The BML reader's options from the conversion's (speech, limits, frames): one place for BML and
// the readers that lower through it (FML-APML, APML).
#pragma once

#include "fapc/bml/bml.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::pipeline::builtin {

bml::BmlOptions bml_options(const ConvertOptions& options);  // format_bml.cpp

}  // namespace fapc::pipeline::builtin

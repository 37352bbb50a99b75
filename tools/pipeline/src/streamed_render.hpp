// Compiling a script without holding its frames: the timeline rendered frame by frame straight
// into the FBA encoder and the .fap writer. Private to the pipeline (convert.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fapc/pipeline/convert.hpp"

namespace fapc::pipeline {

// The conversion, streamed, when it can be: the input is a script (Mimic, FML, XMT-Omega; not
// standard input), every output is .fba or .fap (not gzip, not standard output), the frame rate
// fits an FBA stream, and neither --verify nor facts are asked for. Empty otherwise: the caller
// loads and writes as usual. The outputs, the warnings and the errors are those of the usual
// way, byte for byte.
std::optional<ConvertResult> convert_script_streamed(const std::string& input,
                                                     const std::vector<OutputRequest>& outputs,
                                                     const std::vector<const OutputFormat*>& writers,
                                                     const ConvertOptions& options);

}  // namespace fapc::pipeline

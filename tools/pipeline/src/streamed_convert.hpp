// The one engine's streamed road: an input's frames, one at a time, to writers that take them so,
// without the frames in memory (streamed_convert.cpp). Private to the pipeline (convert.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fapc/pipeline/convert.hpp"

namespace fapc::pipeline {

// The conversion, streamed, when it can be: the input's row gives a frame source (a frame file, a
// script's timeline; not standard input), every output's row a frame writer (not gzip, not
// standard output), and no facts are asked for. Empty otherwise: the caller loads and writes.
// The outputs, the warnings and the errors are those of loading and writing, byte for byte.
std::optional<ConvertResult> convert_streamed(const std::string& input, const std::vector<OutputRequest>& outputs,
                                              const std::vector<const OutputFormat*>& writers,
                                              const ConvertOptions& options);

}  // namespace fapc::pipeline

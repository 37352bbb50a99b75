// The checks of `fapc verify` for inputs that hold an FBA stream (verify.cpp): the rows of .fba
// and .mp4 name them (InputFormat::verify_stream). Private to the pipeline.
#pragma once

#include <string>

#include "fapc/pipeline/verify.hpp"

namespace fapc::pipeline {

// A .fba decodes, and its frames encode again to the same bytes.
VerifyResult verify_fba_file(const std::string& path, const Limits& limits);
// The same for an .mp4's FBA track, sample by sample, durations and sync flags included.
VerifyResult verify_mp4_file(const std::string& path, const Limits& limits);

}  // namespace fapc::pipeline

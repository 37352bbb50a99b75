// The conversion options shared by compile, batch, plot, combine, render, encode, decode, verify
// and info: from the command line (as cli_spec.cpp declares them) to
// fapc::pipeline::ConvertOptions.
#pragma once

#include <string>

#include "fapc/args.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::cli {

using pipeline::ConvertOptions;
using pipeline::PictureSettings;

// Reads the shared options the subcommand declares; sets args' error on bad values.
ConvertOptions convert_options(Args& args);

}  // namespace fapc::cli

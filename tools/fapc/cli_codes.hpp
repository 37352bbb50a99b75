// The command line's diagnostic codes: the constants fapc::codes::AREA::WHAT declared in
// cli_codes.def (and the rows fapc::codes::cli_codes listing them for docs/errors.md).
#pragma once

#include "fapc/codec/codes.hpp"  // the codes every library shares (io, limit)

#define FAPC_CODES_FILE "fapc/cli_codes.def"
#define FAPC_CODES_TABLE cli_codes
#include "fapc/codec/declare_codes.inc"

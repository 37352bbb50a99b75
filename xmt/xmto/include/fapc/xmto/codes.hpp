// The xmto library's diagnostic codes: the constants fapc::codes::AREA::WHAT declared in
// codes.def (and the rows fapc::codes::xmto_codes listing them for docs/errors.md).
#pragma once

#include "fapc/codec/codes.hpp"  // the codes every library shares (io, limit)

#define FAPC_CODES_FILE "fapc/xmto/codes.def"
#define FAPC_CODES_TABLE xmto_codes
#include "fapc/codec/declare_codes.inc"

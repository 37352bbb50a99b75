// The codec library's diagnostic codes: the constants fapc::codes::AREA::WHAT declared in
// codes.def (and the rows fapc::codes::codec_codes listing them for docs/errors.md).
#pragma once

#define FAPC_CODES_FILE "fapc/codec/codes.def"
#define FAPC_CODES_TABLE codec_codes
#include "fapc/codec/declare_codes.inc"

// The timeline model's diagnostic codes: the constants fapc::codes::AREA::WHAT declared in
// timeline_codes.def (and the rows fapc::codes::timeline_codes listing them for docs/errors.md).
#pragma once

#include "fapc/codec/codes.hpp"  // the codes every library shares (io, limit)

#define FAPC_CODES_FILE "fapc/timeline/codes.def"
#define FAPC_CODES_TABLE timeline_codes
#include "fapc/codec/declare_codes.inc"

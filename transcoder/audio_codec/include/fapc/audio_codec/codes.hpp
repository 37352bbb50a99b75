// The audio_codec library's diagnostic codes: the constants fapc::codes::AREA::WHAT declared in
// codes.def (and the rows fapc::codes::audio_codec_codes listing them for docs/errors.md).
#pragma once

#include "fapc/codec/codes.hpp"  // the codes every library shares (io, limit)

#define FAPC_CODES_FILE "fapc/audio_codec/codes.def"
#define FAPC_CODES_TABLE audio_codec_codes
#include "fapc/codec/declare_codes.inc"

// One row of a library's table of diagnostic codes (docs/errors.md): each library declares its
// codes once, in fapc/<library>/codes.def, and its codes.hpp makes from that file both the
// constants the sources pass to make_error / make_warning and the rows listed here, so a code
// cannot be used without being in a table (and in the document made from the tables).
#pragma once

#include "fapc/codec/diagnostic.hpp"

namespace fapc {

struct CodeRow {
  const char* name;     // "fba.truncated"
  Severity severity;    // error or warning
  ErrorKind kind;       // for errors; warnings keep bad_input
  const char* meaning;  // what it means and what to do, one or two sentences
};

}  // namespace fapc

// attributeName of animate and set: which timeline target an XMT-Omega animation drives.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace fapc::xmto {

struct AttributeTarget {
  std::string target;   // the timeline target: a standard FAP name, viseme.X or expression.X
  std::string warning;  // non-empty for the names whose FAP differs between namings
};

// Accepts FAP numbers 3..68 ("3", "fap3"), the ISO/IEC 14496-2 names (the naming the project uses
// everywhere), the four BIFS field names that are no 14496-2 name (stretch_l_corner = 6, ...), and
// viseme.<name> / expression.<name> weights. Empty with `error` set when it is none of these.
std::optional<AttributeTarget> resolve_attribute_name(std::string_view name, std::string& error);

}  // namespace fapc::xmto

// `animation src="..."` (or ref): resolving the path against the including document, refusing
// inclusion cycles, and asking the caller's loader for the timeline.
#pragma once

#include <string>

#include "fapc/codec/include_policy.hpp"  // kMaxIncludeDepth
#include "fapc/xml/xml_document.hpp"
#include "fapc/xmto/xmto.hpp"

namespace fapc::xmt {

struct Included {
  std::string path;  // as resolved
  IncludedAnimation animation;
};

// Errors at the element or its src attribute: no src, a URL that is not a local file, a cycle
// ("a.xmt -> b.xmt -> a.xmt"), nesting deeper than kMaxIncludeDepth, no loader, the loader's own
// error (returned as it is).
Result<Included> load_included(const xml::XmlDocument& doc, const xmlNode* element, const XmtoOptions& options,
                               Diagnostics& warnings);

}  // namespace fapc::xmt

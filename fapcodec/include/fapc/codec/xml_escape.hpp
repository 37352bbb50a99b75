// Text made safe for the XML and HTML fapc writes (XMT-A scenes, SVG plots, JUnit reports, the
// preview page): one escaping for every writer, so none forgets a character.
#pragma once

#include <string>
#include <string_view>

namespace fapc {

// '<', '>', '&' and '"' become entities. As an attribute value (XML 1.0 section 3.3.3) CR, LF and
// TAB also become character references, because a parser would otherwise normalise them to spaces.
enum class XmlPlace { text, attribute };
std::string xml_escape(std::string_view text, XmlPlace place = XmlPlace::text);

}  // namespace fapc

#include "fapc/codec/xml_escape.hpp"

namespace fapc {

std::string xml_escape(std::string_view text, XmlPlace place) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        continue;
      case '>':
        out += "&gt;";
        continue;
      case '&':
        out += "&amp;";
        continue;
      case '"':
        out += "&quot;";
        continue;
      default:
        break;
    }
    if (place == XmlPlace::attribute && (c == '\r' || c == '\n' || c == '\t'))
      out += c == '\r' ? "&#13;" : c == '\n' ? "&#10;" : "&#9;";
    else
      out += c;
  }
  return out;
}

}  // namespace fapc

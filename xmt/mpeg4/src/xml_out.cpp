#include "xml_out.hpp"

namespace fapc::xmt {

namespace {

// An attribute value between double quotes (XML 1.0 §2.4 and §3.3.3): '<' and '&' must be
// escaped, '"' would end the value, '>' is escaped for symmetry; CR, LF and TAB become
// character references because a parser would otherwise normalise them to spaces.
std::string escaped(const std::string& value) {
  std::string out;
  out.reserve(value.size());
  for (const char c : value) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      case '\r': out += "&#13;"; break;
      case '\n': out += "&#10;"; break;
      case '\t': out += "&#9;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

void XmlOut::start_tag(const std::string& name, const XmlAttributes& attributes) {
  text_.append(2 * open_.size(), ' ');
  text_ += '<' + name;
  for (const auto& [key, value] : attributes) text_ += ' ' + key + "=\"" + escaped(value) + '"';
}

void XmlOut::open(const std::string& name, const XmlAttributes& attributes) {
  start_tag(name, attributes);
  text_ += ">\n";
  open_.push_back(name);
}

void XmlOut::empty(const std::string& name, const XmlAttributes& attributes) {
  start_tag(name, attributes);
  text_ += "/>\n";
}

void XmlOut::close() {
  const std::string name = open_.back();
  open_.pop_back();
  text_.append(2 * open_.size(), ' ');
  text_ += "</" + name + ">\n";
}

}  // namespace fapc::xmt

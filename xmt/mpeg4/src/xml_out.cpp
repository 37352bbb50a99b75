#include "xml_out.hpp"

#include "fapc/codec/xml_escape.hpp"

namespace fapc::xmt {

void XmlOut::start_tag(const std::string& name, const XmlAttributes& attributes) {
  text_.append(2 * open_.size(), ' ');
  text_ += '<' + name;
  for (const auto& [key, value] : attributes) text_ += ' ' + key + "=\"" + xml_escape(value, XmlPlace::attribute) + '"';
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

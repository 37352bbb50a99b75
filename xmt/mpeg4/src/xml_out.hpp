// A small indenting XML writer for the documents the project generates. Attribute values are
// escaped with libxml2's own encoder, so no escaping code of our own is needed here.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace fapc::xmt {

using XmlAttributes = std::vector<std::pair<std::string, std::string>>;

class XmlOut {
 public:
  XmlOut() : text_("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n") {}
  void open(const std::string& name, const XmlAttributes& attributes = {});
  void empty(const std::string& name, const XmlAttributes& attributes = {});
  void close();
  std::string take() { return std::move(text_); }

 private:
  void start_tag(const std::string& name, const XmlAttributes& attributes);
  std::string text_;
  std::vector<std::string> open_;
};

}  // namespace fapc::xmt

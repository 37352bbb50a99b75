// A small indenting XML writer for the documents the project generates (XMT-A). It needs no XML
// library: the MPEG-4 layer depends on the codec alone, so MP4 users do not pull in libxml2.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace fapc::mpeg4 {

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

}  // namespace fapc::mpeg4

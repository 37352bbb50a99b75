// Warnings that would repeat for every occurrence (an unsupported element, an ignored attribute)
// are given once per name, at the first occurrence, with the count of all of them.
#pragma once

#include <map>
#include <string>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::xml {

class OncePerName {
 public:
  explicit OncePerName(Diagnostics& out) : out_(out) {}

  // The first report for `key` appends `warning` to the output; later ones only count.
  void report(const std::string& key, Diagnostic warning);
  // Adds "(N times; first here)" to the warnings reported more than once.
  void finish();

 private:
  struct Seen {
    std::size_t index;  // in out_
    int count;
  };
  Diagnostics& out_;
  std::map<std::string, Seen> seen_;
};

// Text (other than blanks) and entity references directly inside `element` carry nothing for the
// readers, and entities are never expanded: both are reported once per element name.
void report_stray_text(const xml::XmlDocument& doc, const xmlNode* element, OncePerName& once);

}  // namespace fapc::xml

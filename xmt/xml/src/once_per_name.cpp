#include "fapc/xml/once_per_name.hpp"

#include <cctype>

namespace fapc::xmt {

void OncePerName::report(const std::string& key, Diagnostic warning) {
  const auto [seen, fresh] = seen_.try_emplace(key, Seen{out_.size(), 0});
  if (fresh) out_.push_back(std::move(warning));
  ++seen->second.count;
}

void OncePerName::finish() {
  for (auto& [key, seen] : seen_) {
    if (seen.count > 1) {
      out_[seen.index].message += " (" + std::to_string(seen.count) + " times; first here)";
      seen.count = 1;
    }
  }
}

void report_stray_text(const xml::XmlDocument& doc, const xmlNode* element, OncePerName& once) {
  const std::string name(xml::local_name(element));
  for (const xmlNode* child = element->children; child; child = child->next) {
    const bool text = child->type == XML_TEXT_NODE || child->type == XML_CDATA_SECTION_NODE;
    const auto blank = [](const xmlChar* content) {
      for (; *content; ++content)
        if (!std::isspace(*content)) return false;
      return true;
    };
    if (text && child->content && !blank(child->content)) {
      once.report("text " + name, doc.warning(element, "text inside " + name + " is ignored"));
    } else if (child->type == XML_ENTITY_REF_NODE) {
      const std::string entity = "&" + std::string(xml::local_name(child)) + ";";
      once.report("entity " + entity, doc.warning(element, "entity reference " + entity + " inside " + name +
                                                               " is not expanded and was ignored"));
    }
  }
}

}  // namespace fapc::xmt

#include "fapc/xml/xml_document.hpp"

#include <libxml/parser.h>

#include <algorithm>
#include <climits>

#include "fapc/codec/nesting_limit.hpp"
#include "xml_tag_scan.hpp"

namespace fapc::xml {
namespace {

// Collects what libxml2 reports during one parse instead of letting it print.
struct ParseReport {
  std::string file;
  std::optional<Diagnostic> first_error;
  Diagnostics warnings;
};

std::string trimmed_message(const char* message) {
  std::string text = message ? message : "unknown XML error";
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

void collect_error(void* user_data, xmlErrorPtr error) {
  auto* context = static_cast<xmlParserCtxtPtr>(user_data);
  auto* report = static_cast<ParseReport*>(context->_private);
  if (!report || !error) return;
  const Location where = Location::text(report->file, std::max(0, error->line), std::max(0, error->int2));
  const std::string message = trimmed_message(error->message);
  if (error->level == XML_ERR_WARNING) {
    report->warnings.push_back(make_warning({"xml.parser"}, where, "XML: " + message));
  } else if (!report->first_error) {
    const char* kind = error->domain == XML_FROM_NAMESPACE ? "XML namespace error: " : "not well-formed XML: ";
    report->first_error = make_error(where, kind + message);
  }
}

// Errors raised outside a parser context would go to libxml2's generic handler, which prints.
void ignore_generic_error(void*, const char*, ...) {}

std::string qualified_element_name(const xmlNode* node) {
  std::string name;
  if (node->ns && node->ns->prefix) name = std::string(reinterpret_cast<const char*>(node->ns->prefix)) + ':';
  return name + reinterpret_cast<const char*>(node->name);
}

void collect_elements(const xmlNode* node, std::vector<const xmlNode*>& out) {
  for (; node; node = node->next) {
    if (node->type != XML_ELEMENT_NODE) continue;
    out.push_back(node);
    collect_elements(node->children, out);
  }
}

const char* text_of(const xmlChar* s) { return reinterpret_cast<const char*>(s); }

}  // namespace

Status check_element_depth(std::string_view text, const std::string& file_name) {
  const std::optional<std::size_t> deep = first_tag_deeper_than(text, kMaxNestingDepth);
  if (!deep) return ok_status();
  const std::size_t line_start = text.rfind('\n', *deep) == std::string_view::npos ? 0 : text.rfind('\n', *deep) + 1;
  const auto line = static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(*deep), '\n')) + 1;
  std::size_t line_end = text.find('\n', *deep);
  if (line_end == std::string_view::npos) line_end = text.size();
  return nesting_too_deep(Location::text(file_name, line, static_cast<int>(*deep - line_start) + 1), "elements",
                          std::string(text.substr(line_start, std::min<std::size_t>(line_end - line_start, 200))));
}

Result<XmlDocument> XmlDocument::parse(std::string_view text, const std::string& file_name) {
  if (text.size() > static_cast<std::size_t>(INT_MAX)) {
    return make_error(ErrorKind::limit_exceeded, Location{file_name, 0, 0, -1}, "file too large for the XML parser");
  }
  // Every walk over the tree recurses; its depth is bounded here, with fapc's error and kind,
  // before libxml2 (which stops at the same depth with a message of its own) sees the text.
  if (Status depth = check_element_depth(text, file_name); !depth) return depth.error();
  xmlInitParser();
  std::unique_ptr<xmlParserCtxt, void (*)(xmlParserCtxtPtr)> context(xmlNewParserCtxt(),
                                                                      xmlFreeParserCtxt);
  if (!context) return make_error(Location{file_name, 0, 0, -1}, "out of memory starting the XML parser");
  ParseReport report{file_name, std::nullopt, {}};
  context->_private = &report;
  context->sax->serror = collect_error;
  xmlSetGenericErrorFunc(nullptr, ignore_generic_error);
  // No network, no DTD loading or defaulted attributes, no entity substitution: an external
  // entity is never fetched and a document reads the same wherever it is.
  xmlDocPtr parsed = xmlCtxtReadMemory(context.get(), text.data(), static_cast<int>(text.size()),
                                       file_name.c_str(), nullptr, XML_PARSE_NONET);
  xmlSetGenericErrorFunc(nullptr, nullptr);
  XmlDocument document;
  document.doc_ = std::shared_ptr<xmlDoc>(parsed, [](xmlDocPtr d) { if (d) xmlFreeDoc(d); });
  document.file_ = file_name;
  document.text_ = std::string(text);
  document.line_starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') document.line_starts_.push_back(i + 1);
  }
  if (report.first_error) return document.with_line(std::move(*report.first_error));
  if (!parsed || !document.root()) {
    return make_error(Location::text(file_name, 1, 1), "not well-formed XML: no root element");
  }
  document.warnings_ = std::move(report.warnings);
  document.index_positions();
  return document;
}

void XmlDocument::index_positions() {
  std::vector<const xmlNode*> elements;
  collect_elements(root(), elements);
  const std::vector<ScannedTag> tags = scan_start_tags(text_);
  // The scan and the tree disagree only for documents whose elements come from entities or whose
  // encoding is not ASCII-compatible; positions then fall back to libxml2's line numbers.
  if (tags.size() != elements.size()) return;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    if (tags[i].name != qualified_element_name(elements[i])) {
      positions_.clear();
      return;
    }
    TagPositions& p = positions_[elements[i]];
    p.tag = at_offset(tags[i].offset);
    for (const auto& [name, offset] : tags[i].attributes) p.attributes.emplace_back(name, at_offset(offset));
  }
}

Location XmlDocument::at_offset(std::size_t offset) const {
  const auto after = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line = static_cast<std::size_t>(after - line_starts_.begin());  // 1-based
  const std::size_t column = offset - line_starts_[line - 1] + 1;
  return Location::text(file_, static_cast<int>(line), static_cast<int>(column));
}

Location XmlDocument::where(const xmlNode* element) const {
  if (const auto found = positions_.find(element); found != positions_.end()) return found->second.tag;
  return Location::text(file_, static_cast<int>(xmlGetLineNo(element)), 0);
}

Location XmlDocument::where(const xmlNode* element, std::string_view attribute) const {
  if (const auto found = positions_.find(element); found != positions_.end()) {
    for (const auto& [name, location] : found->second.attributes) {
      if (name == attribute) return location;
    }
  }
  return where(element);
}

std::string XmlDocument::line_text(int line) const {
  if (line < 1 || static_cast<std::size_t>(line) > line_starts_.size()) return {};
  const std::size_t from = line_starts_[static_cast<std::size_t>(line - 1)];
  std::size_t to = text_.find('\n', from);
  if (to == std::string::npos) to = text_.size();
  if (to > from && text_[to - 1] == '\r') --to;
  return text_.substr(from, to - from);
}

Diagnostic XmlDocument::with_line(Diagnostic d) const {
  d.source_line = line_text(d.where.line);
  return d;
}

Diagnostic XmlDocument::error(const xmlNode* element, std::string message) const {
  return with_line(make_error(where(element), std::move(message)));
}
Diagnostic XmlDocument::error(const xmlNode* element, std::string_view attribute,
                              std::string message) const {
  return with_line(make_error(where(element, attribute), std::move(message)));
}
Diagnostic XmlDocument::warning(const xmlNode* element, std::string message) const {
  return with_line(make_warning(where(element), std::move(message)));
}
Diagnostic XmlDocument::warning(const xmlNode* element, std::string_view attribute,
                                std::string message) const {
  return with_line(make_warning(where(element, attribute), std::move(message)));
}

std::string_view local_name(const xmlNode* node) { return text_of(node->name); }

std::string_view namespace_uri(const xmlNode* node) {
  return node->ns && node->ns->href ? std::string_view(text_of(node->ns->href)) : std::string_view();
}

std::optional<std::string> attribute(const xmlNode* element, const char* name) {
  xmlChar* value = xmlGetNoNsProp(element, reinterpret_cast<const xmlChar*>(name));
  if (!value) return std::nullopt;
  std::string out = text_of(value);
  xmlFree(value);
  return out;
}

std::string qualified_name(const xmlAttr* attr) {
  std::string name;
  if (attr->ns && attr->ns->prefix) name = std::string(text_of(attr->ns->prefix)) + ':';
  return name + text_of(attr->name);
}

std::vector<const xmlNode*> element_children(const xmlNode* element) {
  std::vector<const xmlNode*> out;
  for (const xmlNode* child = element->children; child; child = child->next) {
    if (child->type == XML_ELEMENT_NODE) out.push_back(child);
  }
  return out;
}

std::string text_content(const xmlNode* element) {
  std::string out;
  for (const xmlNode* child = element->children; child; child = child->next) {
    if ((child->type == XML_TEXT_NODE || child->type == XML_CDATA_SECTION_NODE) && child->content) {
      out += text_of(child->content);
    }
  }
  return out;
}

}  // namespace fapc::xml

#include "fapc/xml/xml_document.hpp"

#include <libxml/SAX2.h>
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
  const BlankText* blank_text = nullptr;
};

bool is_blank(const xmlChar* text, int length) {
  for (int i = 0; i < length; ++i)
    if (text[i] != ' ' && text[i] != '\t' && text[i] != '\n' && text[i] != '\r') return false;
  return true;
}

// libxml2's tree builder for text, except white space outside the elements whose text is read
// (BlankText). Also the handler for "ignorable" white space, so that libxml2 never guesses.
void characters(void* user_data, const xmlChar* text, int length) {
  auto* context = static_cast<xmlParserCtxtPtr>(user_data);
  const auto* report = static_cast<const ParseReport*>(context->_private);
  if (report && !report->blank_text->keep_everywhere && context->node && is_blank(text, length)) {
    const std::string_view name = reinterpret_cast<const char*>(context->node->name);
    const auto& kept = report->blank_text->kept_in;
    if (std::find(kept.begin(), kept.end(), name) == kept.end()) return;
  }
  xmlSAX2Characters(user_data, text, length);
}

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

// Whether `written` (a name as the scan found it) is the element's qualified name.
bool is_qualified_name_of(std::string_view written, const xmlNode* node) {
  if (node->ns && node->ns->prefix) {
    const std::string_view prefix = reinterpret_cast<const char*>(node->ns->prefix);
    if (written.size() <= prefix.size() || written.substr(0, prefix.size()) != prefix || written[prefix.size()] != ':')
      return false;
    written.remove_prefix(prefix.size() + 1);
  }
  return written == reinterpret_cast<const char*>(node->name);
}

// The element after `node` in document order (depth first), or null; no recursion, no list.
xmlNode* next_element(xmlNode* node) {
  for (xmlNode* child = node->children; child; child = child->next)
    if (child->type == XML_ELEMENT_NODE) return child;
  for (; node; node = node->parent) {
    for (xmlNode* sibling = node->next; sibling; sibling = sibling->next)
      if (sibling->type == XML_ELEMENT_NODE) return sibling;
    if (!node->parent || node->parent->type != XML_ELEMENT_NODE) return nullptr;
  }
  return nullptr;
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

Result<XmlDocument> XmlDocument::parse(std::string_view text, const std::string& file_name,
                                       const BlankText& blank_text) {
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
  ParseReport report{file_name, std::nullopt, {}, &blank_text};
  context->_private = &report;
  context->sax->serror = collect_error;
  context->sax->characters = characters;
  context->sax->ignorableWhitespace = characters;
  xmlSetGenericErrorFunc(nullptr, ignore_generic_error);
  // No network, no DTD loading or defaulted attributes, no entity substitution: an external
  // entity is never fetched and a document reads the same wherever it is.
  xmlDocPtr parsed = xmlCtxtReadMemory(context.get(), text.data(), static_cast<int>(text.size()),
                                       file_name.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_COMPACT);
  xmlSetGenericErrorFunc(nullptr, nullptr);
  XmlDocument document;
  document.doc_ = std::shared_ptr<xmlDoc>(parsed, [](xmlDocPtr d) { if (d) xmlFreeDoc(d); });
  document.file_ = file_name;
  document.text_ = text;
  document.line_starts_.push_back(0);
  for (std::size_t i = text.find('\n'); i != std::string_view::npos; i = text.find('\n', i + 1))
    document.line_starts_.push_back(static_cast<std::uint32_t>(i + 1));
  if (report.first_error) return document.with_line(std::move(*report.first_error));
  if (!parsed || !document.root()) {
    return make_error(Location::text(file_name, 1, 1), "not well-formed XML: no root element");
  }
  document.warnings_ = std::move(report.warnings);
  document.index_positions();
  return document;
}

void XmlDocument::index_positions() {
  // The scan and the tree disagree only for documents whose elements come from entities or whose
  // encoding is not ASCII-compatible; positions then fall back to libxml2's line numbers.
  bool agree = true;
  xmlNode* element = xmlDocGetRootElement(doc_.get());
  first_attribute_.push_back(0);
  scan_start_tags(text_, [&](const ScannedTagView& tag) {
    if (!agree) return;
    if (!element || !is_qualified_name_of(tag.name, element)) {
      agree = false;
      return;
    }
    tag_offsets_.push_back(static_cast<std::uint32_t>(tag.offset));
    for (const auto& [name, offset] : *tag.attributes) attribute_offsets_.push_back(static_cast<std::uint32_t>(offset));
    first_attribute_.push_back(static_cast<std::uint32_t>(attribute_offsets_.size()));
    // The element's number, for where(): libxml2 leaves _private to the application.
    element->_private = reinterpret_cast<void*>(static_cast<std::uintptr_t>(tag_offsets_.size()));
    element = next_element(element);
  });
  if (agree && !element) {
    tag_offsets_.shrink_to_fit();
    attribute_offsets_.shrink_to_fit();
    first_attribute_.shrink_to_fit();
    return;
  }
  // Disagreement: no element has a position.
  for (xmlNode* e = xmlDocGetRootElement(doc_.get()); e; e = next_element(e)) e->_private = nullptr;
  tag_offsets_ = {};
  first_attribute_ = {};
  attribute_offsets_ = {};
}

std::size_t XmlDocument::number_of(const xmlNode* element) const {
  const auto number = reinterpret_cast<std::uintptr_t>(element->_private);
  return number <= tag_offsets_.size() ? number : 0;
}

Location XmlDocument::at_offset(std::size_t offset) const {
  const auto after = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line = static_cast<std::size_t>(after - line_starts_.begin());  // 1-based
  const std::size_t column = offset - line_starts_[line - 1] + 1;
  return Location::text(file_, static_cast<int>(line), static_cast<int>(column));
}

Location XmlDocument::where(const xmlNode* element) const {
  if (const std::size_t number = number_of(element)) return at_offset(tag_offsets_[number - 1]);
  return Location::text(file_, static_cast<int>(xmlGetLineNo(element)), 0);
}

Location XmlDocument::where(const xmlNode* element, std::string_view attribute) const {
  if (const std::size_t number = number_of(element)) {
    for (std::uint32_t i = first_attribute_[number - 1]; i < first_attribute_[number]; ++i) {
      // The name as written ends where the scan's name ends: at a space, '=', '/' or '>'.
      const std::size_t at = attribute_offsets_[i];
      if (text_.substr(at, attribute.size()) != attribute) continue;
      const std::size_t end = at + attribute.size();
      const char next = end < text_.size() ? text_[end] : ' ';
      if (next == ' ' || next == '\t' || next == '\r' || next == '\n' || next == '=' || next == '/' || next == '>')
        return at_offset(at);
    }
  }
  return where(element);
}

std::string XmlDocument::line_text(int line) const {
  if (line < 1 || static_cast<std::size_t>(line) > line_starts_.size()) return {};
  const std::size_t from = line_starts_[static_cast<std::size_t>(line - 1)];
  std::size_t to = text_.find('\n', from);
  if (to == std::string_view::npos) to = text_.size();
  if (to > from && text_[to - 1] == '\r') --to;
  return std::string(text_.substr(from, to - from));
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

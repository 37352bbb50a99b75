#include "fapc/xml/xml_document.hpp"

#include <libxml/SAX2.h>
#include <libxml/parser.h>

#include <algorithm>
#include <climits>
#include <cstring>

#include "fapc/codec/nesting_limit.hpp"
#include "fapc/xml/codes.hpp"
#include "xml_tag_scan.hpp"

namespace fapc::xml {

namespace {

// Collects what libxml2 reports during one parse instead of letting it print.
struct ParseReport {
  std::string file;
  std::optional<Diagnostic> first_error;
  Diagnostics warnings;
  const BlankText* blank_text = nullptr;
  StreamState* stream = nullptr;  // set when the text is streamed
};

}  // namespace

// A streamed document's push parser and what its SAX handlers learn (see XmlDocument::stream).
struct StreamState {
  std::string_view text;
  XmlDocument::TextReleaser release_text;
  std::size_t fed = 0;  // bytes given to the parser
  bool done = false;    // the parser has the whole text, or stopped at an error
  // Whether the walk sees the document as parse() would (see XmlDocument::stream).
  bool faithful = true;
  BlankText blank_text;
  // Element k (in document order) should be the start tag at tag_offsets[k].
  const std::uint32_t* tag_offsets = nullptr;
  std::size_t tag_count = 0;
  std::size_t started = 0;
  std::unique_ptr<ParseReport> report;  // the parser's _private
  std::unique_ptr<xmlParserCtxt, void (*)(xmlParserCtxtPtr)> context{nullptr, xmlFreeParserCtxt};

  // Gives the parser the next part of the text; false when there is none (or it stopped).
  bool feed();
};

namespace {

bool is_blank(const xmlChar* text, int length) {
  for (int i = 0; i < length; ++i)
    if (text[i] != ' ' && text[i] != '\t' && text[i] != '\n' && text[i] != '\r') return false;
  return true;
}

bool is_kept_in(const BlankText& blank_text, const xmlNode* node) {
  const std::string_view name = reinterpret_cast<const char*>(node->name);
  return std::find(blank_text.kept_in.begin(), blank_text.kept_in.end(), name) != blank_text.kept_in.end();
}

// Streamed, text is kept only in the elements BlankText names (whose children are never freed:
// libxml2 appends text to the last text child it made, which must still be there); elsewhere,
// text other than white space would be reported by the reader in an order a streamed walk does
// not keep: it is dropped and the document is read again whole (parse()).
bool stream_keeps(const ParseReport* report, xmlParserCtxtPtr context, bool blank) {
  if (!context->node || is_kept_in(*report->blank_text, context->node)) return true;
  if (!blank) report->stream->faithful = false;
  return false;
}

// libxml2's tree builder for text, except white space outside the elements whose text is read
// (BlankText). Also the handler for "ignorable" white space, so that libxml2 never guesses.
void characters(void* user_data, const xmlChar* text, int length) {
  auto* context = static_cast<xmlParserCtxtPtr>(user_data);
  const auto* report = static_cast<const ParseReport*>(context->_private);
  if (report && report->stream) {
    if (stream_keeps(report, context, is_blank(text, length))) xmlSAX2Characters(user_data, text, length);
    return;
  }
  if (report && !report->blank_text->keep_everywhere && context->node && is_blank(text, length) &&
      !is_kept_in(*report->blank_text, context->node))
    return;
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
    report->warnings.push_back(make_warning(codes::xml::parser, where, "XML: " + message));
  } else if (!report->first_error) {
    const char* kind = error->domain == XML_FROM_NAMESPACE ? "XML namespace error: " : "not well-formed XML: ";
    report->first_error = make_error(codes::xml::not_well_formed, where, kind + message);
  }
}

// Errors raised outside a parser context would go to libxml2's generic handler, which prints.
void ignore_generic_error(void*, const char*, ...) {}

// ---- streamed documents' SAX handlers: libxml2's tree builder, numbering the elements ----------

StreamState* stream_of(void* user_data) {
  auto* context = static_cast<xmlParserCtxtPtr>(user_data);
  return static_cast<ParseReport*>(context->_private)->stream;
}

bool is_qualified_name_of(std::string_view written, const xmlNode* node);

// The qualified name of the start tag at `offset`, as written.
std::string_view written_name_at(std::string_view text, std::size_t offset) {
  std::size_t end = offset + 1;
  while (end < text.size() && text[end] != ' ' && text[end] != '\t' && text[end] != '\r' && text[end] != '\n' &&
         text[end] != '/' && text[end] != '>')
    ++end;
  return text.substr(offset + 1, end - offset - 1);
}

// _private of an element: its number (1-based, 0: no position) shifted left, and bit 0 set once
// its end tag is read (streamed documents).
void* numbered(std::size_t number) { return reinterpret_cast<void*>(static_cast<std::uintptr_t>(number) << 1); }

void start_element(void* user_data, const xmlChar* local, const xmlChar* prefix, const xmlChar* uri,
                   int namespace_count, const xmlChar** namespaces, int attribute_count, int defaulted_count,
                   const xmlChar** attributes) {
  auto* context = static_cast<xmlParserCtxtPtr>(user_data);
  const xmlNode* before = context->node;
  xmlSAX2StartElementNs(user_data, local, prefix, uri, namespace_count, namespaces, attribute_count, defaulted_count,
                        attributes);
  StreamState& stream = *stream_of(user_data);
  xmlNode* element = context->node;
  if (!element || element == before) {
    stream.faithful = false;
    return;
  }
  const std::size_t k = stream.started++;
  if (k < stream.tag_count && is_qualified_name_of(written_name_at(stream.text, stream.tag_offsets[k]), element)) {
    element->_private = numbered(k + 1);
  } else {
    stream.faithful = false;  // the scan does not place the elements: parse() drops every position
  }
}

void end_element(void* user_data, const xmlChar* local, const xmlChar* prefix, const xmlChar* uri) {
  auto* context = static_cast<xmlParserCtxtPtr>(user_data);
  if (xmlNode* element = context->node)
    element->_private = reinterpret_cast<void*>(reinterpret_cast<std::uintptr_t>(element->_private) | 1);
  xmlSAX2EndElementNs(user_data, local, prefix, uri);
}

void cdata_block(void* user_data, const xmlChar* text, int length) {
  auto* context = static_cast<xmlParserCtxtPtr>(user_data);
  if (stream_keeps(static_cast<const ParseReport*>(context->_private), context, false))
    xmlSAX2CDataBlock(user_data, text, length);
}

// Entity references are reported by the readers where they are: not in a streamed walk.
void entity_reference(void* user_data, const xmlChar*) { stream_of(user_data)->faithful = false; }

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
  const auto line =
      static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(*deep), '\n')) + 1;
  std::size_t line_end = text.find('\n', *deep);
  if (line_end == std::string_view::npos) line_end = text.size();
  return nesting_too_deep(Location::text(file_name, line, static_cast<int>(*deep - line_start) + 1), "elements",
                          std::string(text.substr(line_start, std::min<std::size_t>(line_end - line_start, 200))));
}

Result<XmlDocument> XmlDocument::parse(std::string_view text, const std::string& file_name,
                                       const BlankText& blank_text) {
  if (text.size() > static_cast<std::size_t>(INT_MAX)) {
    return make_error(codes::xml::too_large, Location::whole_file(file_name), "file too large for the XML parser");
  }
  // Every walk over the tree recurses; its depth is bounded here, with fapc's error and kind,
  // before libxml2 (which stops at the same depth with a message of its own) sees the text.
  if (Status depth = check_element_depth(text, file_name); !depth) return depth.error();
  xmlInitParser();
  std::unique_ptr<xmlParserCtxt, void (*)(xmlParserCtxtPtr)> context(xmlNewParserCtxt(), xmlFreeParserCtxt);
  if (!context)
    return make_error(codes::xml::parser_failed, Location::whole_file(file_name),
                      "out of memory starting the XML parser");
  ParseReport report{file_name, std::nullopt, {}, &blank_text};
  context->_private = &report;
  context->sax->serror = collect_error;
  context->sax->characters = characters;
  context->sax->ignorableWhitespace = characters;
  xmlSetGenericErrorFunc(nullptr, ignore_generic_error);
  // No network, no DTD loading or defaulted attributes, no entity substitution: an external
  // entity is never fetched and a document reads the same wherever it is.
  xmlDocPtr parsed = xmlCtxtReadMemory(context.get(), text.data(), static_cast<int>(text.size()), file_name.c_str(),
                                       nullptr, XML_PARSE_NONET | XML_PARSE_COMPACT);
  xmlSetGenericErrorFunc(nullptr, nullptr);
  XmlDocument document;
  document.doc_ = std::shared_ptr<xmlDoc>(parsed, [](xmlDocPtr d) {
    if (d) xmlFreeDoc(d);
  });
  document.file_ = file_name;
  document.text_ = text;
  document.index_lines();
  if (report.first_error) return document.with_line(std::move(*report.first_error));
  if (!parsed || !document.root()) {
    return make_error(codes::xml::no_root, Location::text(file_name, 1, 1), "not well-formed XML: no root element");
  }
  document.warnings_ = std::move(report.warnings);
  document.index_positions();
  return document;
}

void XmlDocument::index_lines() {
  line_starts_.push_back(0);
  for (std::size_t i = text_.find('\n'); i != std::string_view::npos; i = text_.find('\n', i + 1))
    line_starts_.push_back(static_cast<std::uint32_t>(i + 1));
}

XmlDocument::XmlDocument() = default;
XmlDocument::XmlDocument(XmlDocument&&) noexcept = default;
XmlDocument& XmlDocument::operator=(XmlDocument&&) noexcept = default;
XmlDocument::~XmlDocument() = default;

namespace {
constexpr std::size_t kStreamChunk = 64 * 1024;  // what the tree may run ahead of the walk
}

bool StreamState::feed() {
  if (done) return false;
  const std::size_t size = std::min(kStreamChunk, text.size() - fed);
  const bool last = fed + size == text.size();
  xmlSetGenericErrorFunc(nullptr, ignore_generic_error);
  xmlParseChunk(context.get(), text.data() + fed, static_cast<int>(size), last ? 1 : 0);
  xmlSetGenericErrorFunc(nullptr, nullptr);
  fed += size;
  if (release_text) release_text(fed);  // the parser keeps what it still needs
  if (report->first_error || !report->warnings.empty()) faithful = false;
  if (last || report->first_error) done = true;
  return true;
}

Result<XmlDocument> XmlDocument::stream(std::string_view text, const std::string& file_name,
                                        const BlankText& blank_text, TextReleaser release_text) {
  if (text.size() > static_cast<std::size_t>(INT_MAX)) {
    return make_error(codes::xml::too_large, Location::whole_file(file_name), "file too large for the XML parser");
  }
  xmlInitParser();
  XmlDocument document;
  document.file_ = file_name;
  document.text_ = text;
  document.index_lines();
  document.first_attribute_.push_back(0);
  // One scan places the tags and checks the depth (an error here is given again, as before, by
  // the caller's parse()).
  bool too_deep = false;
  scan_start_tags(text, [&](const ScannedTagView& tag) {
    too_deep = too_deep || (!tag.empty && tag.depth + 1 > static_cast<std::size_t>(kMaxNestingDepth));
    document.add_tag(tag.offset, tag.parent, *tag.attributes);
  });
  if (too_deep)
    return make_error(codes::limit::nesting_depth, Location::text(file_name, 1, 1), "elements nested too deep");
  document.shrink_positions();
  // The scans touched every page; the parser reads them again one part at a time.
  if (release_text) release_text(text.size());
  document.release_text_ = release_text;

  auto state = std::make_unique<StreamState>();
  state->text = text;
  state->release_text = std::move(release_text);
  state->blank_text = blank_text;
  state->tag_offsets = document.tag_offsets_.data();
  state->tag_count = document.tag_offsets_.size();
  auto report =
      std::make_unique<ParseReport>(ParseReport{file_name, std::nullopt, {}, &state->blank_text, state.get()});
  // The first bytes tell the parser the encoding.
  state->fed = std::min<std::size_t>(4, text.size());
  state->context.reset(
      xmlCreatePushParserCtxt(nullptr, nullptr, text.data(), static_cast<int>(state->fed), file_name.c_str()));
  xmlParserCtxtPtr context = state->context.get();
  if (!context)
    return make_error(codes::xml::parser_failed, Location::whole_file(file_name),
                      "out of memory starting the XML parser");
  xmlCtxtUseOptions(context, XML_PARSE_NONET | XML_PARSE_COMPACT);
  context->_private = report.get();
  context->sax->serror = collect_error;
  context->sax->characters = characters;
  context->sax->ignorableWhitespace = characters;
  context->sax->cdataBlock = cdata_block;
  context->sax->reference = entity_reference;
  context->sax->startElementNs = start_element;
  context->sax->endElementNs = end_element;
  // Comments and processing instructions carry nothing for the readers.
  context->sax->comment = nullptr;
  context->sax->processingInstruction = nullptr;
  state->report = std::move(report);
  document.stream_ = std::move(state);
  document.streamed_ = true;
  while (!(context->myDoc && xmlDocGetRootElement(context->myDoc)) && document.stream_->feed()) {
  }
  if (context->myDoc) document.doc_ = std::shared_ptr<xmlDoc>(context->myDoc, [](xmlDocPtr d) { xmlFreeDoc(d); });
  if (!document.root() || !document.stream_->faithful)
    return make_error(codes::xml::no_root, Location::text(file_name, 1, 1), "not well-formed XML: no root element");
  return document;
}

bool XmlDocument::finish_stream() {
  if (stream_) {
    while (stream_->feed()) {
    }
    if (!stream_->faithful || stream_->started != tag_offsets_.size()) faithful_ = false;
    stream_.reset();
  }
  return faithful_;
}

void XmlDocument::abandon_stream() const { faithful_ = false; }

void XmlDocument::release_tree() {
  finish_stream();
  released_ = true;
  doc_.reset();
  if (release_text_) release_text_(text_.size());
  // Positions are asked of nodes, and there are none left (line_text() stays).
  drop_positions();
}

bool XmlDocument::ended(const xmlNode* element) const {
  return !stream_ || (reinterpret_cast<std::uintptr_t>(element->_private) & 1) != 0;
}

void XmlDocument::release(const xmlNode* element) const {
  auto* node = const_cast<xmlNode*>(element);
  xmlUnlinkNode(node);
  xmlFreeNode(node);
}

const xmlNode* XmlDocument::next_child(const xmlNode* parent, const xmlNode* after, OpenNames open) const {
  for (;;) {
    const xmlNode* node = after ? after->next : parent->children;
    while (node && node->type != XML_ELEMENT_NODE) {
      after = node;
      node = node->next;
    }
    if (node) {
      if (ended(node) || std::find(open.begin(), open.end(), local_name(node)) != open.end()) return node;
    } else if (ended(parent)) {
      return nullptr;
    }
    // Streamed, and what is asked for is not read yet: read on, or take what there is if the
    // parser has stopped (the document is then read again whole).
    if (!stream_->feed()) {
      stream_->faithful = false;
      return node;
    }
  }
}

ChildWalk::iterator ChildWalk::begin() const {
  iterator first;
  first.walk_ = this;
  first.current_ = doc_.next_child(parent_, nullptr, open_);
  return first;
}

ChildWalk::iterator& ChildWalk::iterator::operator++() {
  const ChildWalk& walk = *walk_;
  const xmlNode* after = current_;
  if (walk.release_ && walk.doc_.stream_ && walk.doc_.ended(current_)) {
    after = current_->prev;
    walk.doc_.release(current_);
  }
  current_ = walk.doc_.next_child(walk.parent_, after, walk.open_);
  return *this;
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
    add_tag(tag.offset, tag.parent, *tag.attributes);
    // The element's number, for where(): libxml2 leaves _private to the application.
    element->_private = numbered(tag_offsets_.size());
    element = next_element(element);
  });
  if (agree && !element) {
    shrink_positions();
    return;
  }
  // Disagreement: no element has a position.
  for (xmlNode* e = xmlDocGetRootElement(doc_.get()); e; e = next_element(e)) e->_private = nullptr;
  drop_positions();
}

void XmlDocument::add_tag(std::size_t offset, std::size_t parent,
                          const std::vector<std::pair<std::string_view, std::size_t>>& attributes) {
  tag_offsets_.push_back(static_cast<std::uint32_t>(offset));
  for (const auto& [name, at] : attributes) attribute_offsets_.push_back(static_cast<std::uint32_t>(at));
  first_attribute_.push_back(static_cast<std::uint32_t>(attribute_offsets_.size()));
  child_counts_.push_back(0);
  if (parent) ++child_counts_[parent - 1];
}

void XmlDocument::drop_positions() {
  // Assigning {} would keep each vector's capacity (it is an empty initializer list): swap with
  // empty ones so the memory goes.
  std::vector<std::uint32_t>().swap(tag_offsets_);
  std::vector<std::uint32_t>().swap(first_attribute_);
  std::vector<std::uint32_t>().swap(attribute_offsets_);
  std::vector<std::uint32_t>().swap(child_counts_);
}

void XmlDocument::shrink_positions() {
  tag_offsets_.shrink_to_fit();
  attribute_offsets_.shrink_to_fit();
  first_attribute_.shrink_to_fit();
  child_counts_.shrink_to_fit();
}

std::size_t XmlDocument::number_of(const xmlNode* element) const {
  const auto number = reinterpret_cast<std::uintptr_t>(element->_private) >> 1;
  return number <= tag_offsets_.size() ? number : 0;
}

Location XmlDocument::at_offset(std::size_t offset) const {
  // Readers ask in document order, mostly a line or two on from the last answer.
  auto after = line_starts_.begin() + static_cast<std::ptrdiff_t>(line_hint_);
  if (*(after - 1) <= offset) {
    for (int step = 0; step < 4 && after != line_starts_.end() && *after <= offset; ++step) ++after;
    if (after != line_starts_.end() && *after <= offset) after = std::upper_bound(after, line_starts_.end(), offset);
  } else {
    after = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  }
  line_hint_ = static_cast<std::size_t>(after - line_starts_.begin());
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

Diagnostic XmlDocument::error(ErrorCode code, const xmlNode* element, std::string message) const {
  return with_line(make_error(code, where(element), std::move(message)));
}
Diagnostic XmlDocument::error(ErrorCode code, const xmlNode* element, std::string_view attribute,
                              std::string message) const {
  return with_line(make_error(code, where(element, attribute), std::move(message)));
}
Diagnostic XmlDocument::warning(const xmlNode* element, std::string message) const {
  return with_line(make_warning(where(element), std::move(message)));
}
Diagnostic XmlDocument::warning(const xmlNode* element, std::string_view attribute, std::string message) const {
  return with_line(make_warning(where(element, attribute), std::move(message)));
}

std::string_view local_name(const xmlNode* node) { return text_of(node->name); }

std::string_view namespace_uri(const xmlNode* node) {
  return node->ns && node->ns->href ? std::string_view(text_of(node->ns->href)) : std::string_view();
}

std::optional<std::string> attribute(const xmlNode* element, const char* name) {
  // The common case read directly (libxml2 copies every value it returns): a value of one text
  // node, or none. Values with entity references, and the defaults a DTD may give, as libxml2
  // gives them.
  if (!element->doc || (!element->doc->intSubset && !element->doc->extSubset)) {
    const xmlAttr* attr = element->properties;
    while (attr && (attr->ns || std::strcmp(text_of(attr->name), name) != 0)) attr = attr->next;
    if (!attr) return std::nullopt;
    const xmlNode* value = attr->children;
    if (!value) return std::string();
    if (value->type == XML_TEXT_NODE && !value->next && value->content) return std::string(text_of(value->content));
  }
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

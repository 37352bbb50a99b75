// A parsed XML document that knows where each element and attribute starts in the source text.
// libxml2 gives an element only the line where its start tag *ends* and no column, while
// diagnostics want file:line:col of the tag and of the offending attribute; so the start tags are
// also located in the text (xml_tag_scan.hpp) and matched to the elements in document order.
// Parsing is safe for untrusted input: no network, no DTD loading, no entity substitution.
#pragma once

#include <libxml/tree.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::xml {

// Text that consists of white space only (the indentation between elements) is most of a large
// document's nodes; a reader that only asks whether an element holds text other than white space
// lets the parser drop it everywhere except in the elements whose text it reads.
struct BlankText {
  bool keep_everywhere = true;
  std::vector<std::string_view> kept_in;  // local names of the elements whose text is read
};

class XmlDocument {
 public:
  // Errors: not well-formed (libxml2's message at its line:col), namespace errors, a text larger
  // than libxml2 takes. Warnings of the parser are kept in warnings(). The document refers to
  // `text` (for positions and source lines) without copying it: the text must outlive it.
  static Result<XmlDocument> parse(std::string_view text, const std::string& file_name,
                                   const BlankText& blank_text = {});

  const xmlNode* root() const { return xmlDocGetRootElement(doc_.get()); }
  // Frees libxml2's tree (the bulk of the memory) once a reader has taken what it needs from the
  // nodes; line_text() and the positions of number_of() stay. No node may be used after it.
  void release_tree() { doc_.reset(); }
  // How many elements the document has (0 when positions are unknown): a bound for reserving.
  std::size_t element_count() const { return tag_offsets_.size(); }
  const std::string& file() const { return file_; }
  const Diagnostics& warnings() const { return warnings_; }

  // The '<' of the element's start tag; the start of an attribute's name (its qualified name as
  // written, e.g. "dur" or "xlink:href"), or the tag when the attribute is absent.
  Location where(const xmlNode* element) const;
  Location where(const xmlNode* element, std::string_view attribute) const;
  std::string line_text(int line) const;

  // Diagnostics at an element (or one of its attributes) with the source line for the caret.
  Diagnostic error(const xmlNode* element, std::string message) const;
  Diagnostic error(const xmlNode* element, std::string_view attribute, std::string message) const;
  Diagnostic warning(const xmlNode* element, std::string message) const;
  Diagnostic warning(const xmlNode* element, std::string_view attribute, std::string message) const;

 private:
  std::shared_ptr<xmlDoc> doc_;
  std::string file_;
  std::string_view text_;
  std::vector<std::uint32_t> line_starts_;
  // Positions, by element number: element k (in document order, kept in its node's _private as
  // k + 1) starts at tag_offsets_[k]; its attributes, as written, start at the offsets
  // attribute_offsets_[first_attribute_[k] .. first_attribute_[k + 1]). A few bytes per element
  // and attribute, where a map from nodes to Locations cost hundreds.
  std::vector<std::uint32_t> tag_offsets_;
  std::vector<std::uint32_t> first_attribute_;
  std::vector<std::uint32_t> attribute_offsets_;
  Diagnostics warnings_;

  Location at_offset(std::size_t offset) const;
  // The element's number + 1, 0 when positions are unknown (libxml2's line numbers then).
  std::size_t number_of(const xmlNode* element) const;
  void index_positions();
  Diagnostic with_line(Diagnostic d) const;
};

// Elements nested deeper than kMaxNestingDepth: an error at the first start tag too deep
// (ErrorKind::limit_exceeded). Every reader of XML text (parse, validation) checks it first.
Status check_element_depth(std::string_view text, const std::string& file_name);

// ---- small helpers on libxml2 nodes ----------------------------------------------------------

std::string_view local_name(const xmlNode* node);
// The element's namespace URI, empty when it has none.
std::string_view namespace_uri(const xmlNode* node);
// The value of an attribute in no namespace (the SMIL attributes), if present.
std::optional<std::string> attribute(const xmlNode* element, const char* name);
// The attribute's name as written in the source: "prefix:local" or "local".
std::string qualified_name(const xmlAttr* attribute);
// Element children in document order.
std::vector<const xmlNode*> element_children(const xmlNode* element);
// The text of an element (its text and CDATA children concatenated).
std::string text_content(const xmlNode* element);

}  // namespace fapc::xml

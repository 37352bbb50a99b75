// A parsed XML document that knows where each element and attribute starts in the source text.
// libxml2 gives an element only the line where its start tag *ends* and no column, while
// diagnostics want file:line:col of the tag and of the offending attribute; so the start tags are
// also located in the text (xml_tag_scan.hpp) and matched to the elements in document order.
// Parsing is safe for untrusted input: no network, no DTD loading, no entity substitution.
#pragma once

#include <libxml/tree.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
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

class XmlDocument;

// The local names of the elements a walk hands out as soon as their start tag is read (see
// XmlDocument::children): the containers a reader walks child by child.
using OpenNames = std::span<const std::string_view>;

// The element children of one element, in document order, as a range for `for`.
class ChildWalk {
 public:
  class iterator {
   public:
    const xmlNode* operator*() const { return current_; }
    iterator& operator++();
    bool operator!=(const iterator& other) const { return current_ != other.current_; }

   private:
    friend class ChildWalk;
    const ChildWalk* walk_ = nullptr;
    const xmlNode* current_ = nullptr;
  };
  iterator begin() const;
  iterator end() const { return {}; }

 private:
  friend class XmlDocument;
  ChildWalk(const XmlDocument& doc, const xmlNode* parent, OpenNames open, bool release)
      : doc_(doc), parent_(parent), open_(open), release_(release) {}
  const XmlDocument& doc_;
  const xmlNode* parent_;
  OpenNames open_;
  bool release_;
};

struct StreamState;

class XmlDocument {
 public:
  XmlDocument();
  XmlDocument(XmlDocument&&) noexcept;
  XmlDocument& operator=(XmlDocument&&) noexcept;
  ~XmlDocument();

  // Errors: not well-formed (libxml2's message at its line:col), namespace errors, a text larger
  // than libxml2 takes. Warnings of the parser are kept in warnings(). The document refers to
  // `text` (for positions and source lines) without copying it: the text must outlive it.
  static Result<XmlDocument> parse(std::string_view text, const std::string& file_name,
                                   const BlankText& blank_text = {});

  // The same document read as the readers walk it, for texts too large to hold as a tree (libxml2
  // takes about 1 KB per element): children() reads the text only as far as the walk needs and
  // frees, when asked, the children it has passed, so the tree alive is the path being read. The
  // readers' code is the same for both; what a streamed walk cannot see as a whole parse does (text
  // or entity references where the readers report them, a warning of the parser, an error
  // anywhere, an element the tag scan does not place) makes finish_stream() false, and the caller
  // then reads the text again with parse(), which gives every message as before.
  // `release_text(offset)`, when given, is told as the parser passes each part of the text that
  // it may drop the pages before `offset` (SourceText::release: they come back if looked at
  // again, for a message's source line), and the whole text once the tree is released.
  using TextReleaser = std::function<void(std::size_t offset)>;
  static Result<XmlDocument> stream(std::string_view text, const std::string& file_name,
                                    const BlankText& blank_text = {}, TextReleaser release_text = {});
  bool streamed() const { return streamed_; }
  // Reads the rest of a streamed text (no-op for a parsed one). True when the reader's result
  // stands: see stream(). Called by release_tree().
  bool finish_stream();
  // A reader met something whose messages a streamed walk would give in another order than
  // parse(): finish_stream() will be false.
  void abandon_stream() const;

  // Element children of `element` in document order. Streamed: a child whose local name is in
  // `open` comes as soon as its start tag is read (its own children are read by a walk of their
  // own), any other once its end tag is; with `release`, each child the walk has passed is freed
  // with its subtree (no pointer into it may be kept). Parsed: simply the children.
  ChildWalk children(const xmlNode* element, OpenNames open = {}, bool release = false) const {
    return ChildWalk(*this, element, open, release);
  }

  const xmlNode* root() const { return xmlDocGetRootElement(doc_.get()); }
  // Frees libxml2's tree and the elements' positions once a reader has taken what it needs from
  // the nodes; line_text() stays. No node may be used after it.
  void release_tree();
  bool tree_released() const { return released_; }
  // How many elements the document has (0 when positions are unknown): a bound for reserving.
  std::size_t element_count() const { return tag_offsets_.size(); }
  // How many element children `element` has in the text (0 when positions are unknown): a bound
  // for reserving.
  std::size_t child_count(const xmlNode* element) const {
    const std::size_t number = number_of(element);
    return number ? child_counts_[number - 1] : 0;
  }
  const std::string& file() const { return file_; }
  const Diagnostics& warnings() const { return warnings_; }

  // The '<' of the element's start tag; the start of an attribute's name (its qualified name as
  // written, e.g. "dur" or "xlink:href"), or the tag when the attribute is absent.
  Location where(const xmlNode* element) const;
  Location where(const xmlNode* element, std::string_view attribute) const;
  std::string line_text(int line) const;

  // Diagnostics at an element (or one of its attributes) with the source line for the caret.
  Diagnostic error(ErrorCode code, const xmlNode* element, std::string message) const;
  Diagnostic error(ErrorCode code, const xmlNode* element, std::string_view attribute, std::string message) const;
  Diagnostic warning(const xmlNode* element, std::string message) const;
  Diagnostic warning(const xmlNode* element, std::string_view attribute, std::string message) const;

 private:
  std::shared_ptr<xmlDoc> doc_;
  std::string file_;
  std::string_view text_;
  TextReleaser release_text_;  // streamed: see stream()
  std::vector<std::uint32_t> line_starts_;
  mutable std::size_t line_hint_ = 1;  // where at_offset() found the last line: 1 + its index
  // Positions, by element number: element k (in document order, kept in its node's _private as
  // (k + 1) << 1; bit 0 marks an element whose end tag a streamed parse has read) starts at tag_offsets_[k]; its
  // attributes, as written, start at the offsets attribute_offsets_[first_attribute_[k] .. first_attribute_[k + 1]). A
  // few bytes per element and attribute, where a map from nodes to Locations cost hundreds.
  std::vector<std::uint32_t> tag_offsets_;
  std::vector<std::uint32_t> first_attribute_;
  std::vector<std::uint32_t> attribute_offsets_;
  std::vector<std::uint32_t> child_counts_;  // by element number - 1
  Diagnostics warnings_;
  std::unique_ptr<StreamState> stream_;  // a streamed document's parser, null once finished
  bool streamed_ = false;
  bool released_ = false;
  mutable bool faithful_ = true;

  friend class ChildWalk;
  friend struct StreamState;
  // The element child after `after` (the first when null), waiting, when streamed, until it is
  // there (and complete unless its name is in `open`); null when there is none.
  const xmlNode* next_child(const xmlNode* parent, const xmlNode* after, OpenNames open) const;
  bool ended(const xmlNode* element) const;
  void release(const xmlNode* element) const;

  Location at_offset(std::size_t offset) const;
  // The element's number + 1, 0 when positions are unknown (libxml2's line numbers then).
  std::size_t number_of(const xmlNode* element) const;
  void index_positions();
  void index_lines();
  void add_tag(std::size_t offset, std::size_t parent,
               const std::vector<std::pair<std::string_view, std::size_t>>& attributes);
  void shrink_positions();
  void drop_positions();  // frees the position tables
  Diagnostic with_line(Diagnostic d) const;
};

// A reader's walk (`read(document)`, giving a Result) over `text` streamed, and again over the
// whole parsed tree when the streamed walk cannot stand for it (see XmlDocument::stream): what
// the FML and XMT-Omega readers do with every document.
template <class Read>
auto read_streamed_or_whole(std::string_view text, const std::string& file_name, const BlankText& blank_text,
                            const XmlDocument::TextReleaser& release_text, Read read)
    -> decltype(read(std::declval<XmlDocument&>())) {
  if (Result<XmlDocument> streamed = XmlDocument::stream(text, file_name, blank_text, release_text)) {
    auto result = read(*streamed);
    // An error the reader met after letting the tree go (scheduling, the frame limit) comes from
    // what it took from the walk: when the walk was faithful, a whole parse gives the same error.
    if ((result || streamed->tree_released()) && streamed->finish_stream()) return result;
  }
  Result<XmlDocument> parsed = XmlDocument::parse(text, file_name, blank_text);
  if (!parsed) return parsed.error();
  return read(*parsed);
}

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

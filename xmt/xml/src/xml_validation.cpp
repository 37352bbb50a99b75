// Xerces-C validation: a progressive SAX2 parse finds the root element, then a full parse
// validates against the one cached grammar the root selects. Xerces stays inside this file.
#include "fapc/xml/xml_validation.hpp"

#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <set>

#include <xercesc/framework/MemBufInputSource.hpp>
#include <xercesc/framework/XMLPScanToken.hpp>
#include <xercesc/framework/XMLValidityCodes.hpp>
#include <xercesc/parsers/SAX2XMLReaderImpl.hpp>
#include <xercesc/sax/EntityResolver.hpp>
#include <xercesc/sax/Locator.hpp>
#include <xercesc/sax/SAXException.hpp>
#include <xercesc/sax/SAXParseException.hpp>
#include <xercesc/sax2/Attributes.hpp>
#include <xercesc/sax2/DefaultHandler.hpp>
#include <xercesc/sax2/SAX2XMLReader.hpp>
#include <xercesc/util/PlatformUtils.hpp>
#include <xercesc/util/SecurityManager.hpp>
#include <xercesc/util/XMLException.hpp>
#include <xercesc/util/XMLString.hpp>
#include <xercesc/validators/common/Grammar.hpp>

#include "fapc/codec/deep_stack.hpp"
#include "schema_registry.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::xmt {

namespace {

namespace xc = XERCES_CPP_NAMESPACE;

// Xerces must be initialised once per process before any use; it is never terminated, because
// other parts of the program may still use it at exit.
void initialise_xerces() {
  static std::once_flag once;
  std::call_once(once, [] { xc::XMLPlatformUtils::Initialize(); });
}

std::string text(const XMLCh* s) {
  if (!s) return {};
  char* chars = xc::XMLString::transcode(s);
  std::string out(chars);
  xc::XMLString::release(&chars);
  return out;
}

class XmlCh {  // an owned Xerces string
 public:
  explicit XmlCh(const std::string& s) : value_(xc::XMLString::transcode(s.c_str())) {}
  ~XmlCh() { xc::XMLString::release(&value_); }
  XmlCh(const XmlCh&) = delete;
  XmlCh& operator=(const XmlCh&) = delete;
  const XMLCh* get() const { return value_; }

 private:
  XMLCh* value_;
};

// XMT-Omega's NumberList ("0; 100; 50", a trailing ';' allowed), as the form its schema type
// documents: \s*N\s*(;\s*N\s*)*;?\s* with N = [+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?. Checked
// here, in one pass, because Xerces-C's matcher recurses once per item of such a pattern.
bool is_number_list(std::string_view s) {
  std::size_t i = 0;
  const auto spaces = [&] {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
  };
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i > from;
  };
  const auto sign = [&] {
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  };
  const auto number = [&] {
    sign();
    if (digits()) {
      if (i < s.size() && s[i] == '.') {
        ++i;
        digits();
      }
    } else if (i < s.size() && s[i] == '.') {
      ++i;
      if (!digits()) return false;
    } else {
      return false;
    }
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
      ++i;
      sign();
      if (!digits()) return false;
    }
    return true;
  };
  spaces();
  if (!number()) return false;
  spaces();
  while (i < s.size() && s[i] == ';') {
    ++i;
    spaces();
    if (i == s.size()) return true;
    if (!number()) return false;
    spaces();
  }
  return i == s.size();
}

// Collects problems with their positions; remembers the root element when asked to.
class Collector : public xc::DefaultHandler {
 public:
  explicit Collector(const std::string& file, bool xmto_lists = false) : file_(file), xmto_lists_(xmto_lists) {}

  void setDocumentLocator(const xc::Locator* locator) override { locator_ = locator; }

  void startElement(const XMLCh* uri, const XMLCh* local, const XMLCh*, const xc::Attributes& attributes) override {
    if (!root_seen) {
      root_seen = true;
      root_ns = text(uri);
      root_name = text(local);
    }
    if (xmto_lists_ && text(local) == "animate") check_number_lists(attributes);
  }
  void warning(const xc::SAXParseException& e) override { add(Severity::warning, e); }
  void error(const xc::SAXParseException& e) override { add(Severity::error, e); }
  void fatalError(const xc::SAXParseException& e) override { add(Severity::error, e); }

  // Nothing outside the document is ever read: DTDs and entities named by it resolve to nothing.
  xc::InputSource* resolveEntity(const XMLCh*, const XMLCh*) override {
    static const XMLByte nothing[] = "";
    return new xc::MemBufInputSource(nothing, 0, "", false);
  }

  bool root_seen = false;
  std::string root_ns, root_name;
  Diagnostics problems;
  // Which problems (indices into `problems`) are IDREFs naming no ID (Xerces reports those at
  // the end of the document).
  std::set<std::size_t> unresolved_references;
  // Set by CodedReader around each report: what Xerces' error code says the next problem is.
  bool next_is_unresolved_reference = false;

 private:
  // values and keyTimes of an XMT-Omega animate (their schema type checks only the characters).
  void check_number_lists(const xc::Attributes& attributes) {
    for (XMLSize_t i = 0; i < attributes.getLength(); ++i) {
      const std::string name = text(attributes.getLocalName(i));
      if (name != "values" && name != "keyTimes") continue;
      const std::string value = text(attributes.getValue(i));
      if (is_number_list(value)) continue;
      const int line = locator_ ? static_cast<int>(locator_->getLineNumber()) : 0;
      const int column = locator_ ? static_cast<int>(locator_->getColumnNumber()) : 0;
      const std::string shown = value.size() > 40 ? value.substr(0, 40) + "..." : value;
      problems.push_back(make_error(Location::text(file_, line, column),
                                    "'" + name + "': '" + shown + "' is not a list of numbers separated by ';'"));
    }
  }

  void add(Severity severity, const xc::SAXParseException& e) {
    problems.push_back(Diagnostic{severity,
                                  Location::text(file_, static_cast<int>(e.getLineNumber()),
                                                 static_cast<int>(e.getColumnNumber())),
                                  text(e.getMessage()), {}});
    if (next_is_unresolved_reference) unresolved_references.insert(problems.size() - 1);
  }
  const std::string& file_;
  bool xmto_lists_;
  const xc::Locator* locator_ = nullptr;
};

// The SAX2 reader, seeing each error's code before the SAX handler gets only its text: the
// collector learns what a problem is without reading its wording.
class CodedReader : public xc::SAX2XMLReaderImpl {
 public:
  explicit CodedReader(Collector& collector) : collector_(collector) {}
  void error(const unsigned int code, const XMLCh* const domain, const xc::XMLErrorReporter::ErrTypes type,
             const XMLCh* const message, const XMLCh* const system_id, const XMLCh* const public_id,
             const XMLFileLoc line, const XMLFileLoc column) override {
    collector_.next_is_unresolved_reference =
        code == xc::XMLValid::IDNotDeclared && xc::XMLString::equals(domain, xc::XMLUni::fgValidityDomain);
    xc::SAX2XMLReaderImpl::error(code, domain, type, message, system_id, public_id, line, column);
    collector_.next_is_unresolved_reference = false;
  }

 private:
  Collector& collector_;
};

struct ReaderDeleter {
  void operator()(xc::SAX2XMLReader* r) const { delete r; }
};
using Reader = std::unique_ptr<xc::SAX2XMLReader, ReaderDeleter>;

Reader make_reader(Collector& collector, xc::SecurityManager& security, bool validate) {
  Reader reader(new CodedReader(collector));
  reader->setFeature(xc::XMLUni::fgSAX2CoreNameSpaces, true);
  reader->setFeature(xc::XMLUni::fgXercesLoadExternalDTD, false);
  reader->setFeature(xc::XMLUni::fgXercesDisableDefaultEntityResolution, true);
  reader->setFeature(xc::XMLUni::fgXercesLoadSchema, false);  // never follow xsi:schemaLocation
  reader->setFeature(xc::XMLUni::fgSAX2CoreValidation, validate);
  reader->setFeature(xc::XMLUni::fgXercesDynamic, false);
  reader->setFeature(xc::XMLUni::fgXercesSchema, validate);
  reader->setFeature(xc::XMLUni::fgXercesSchemaFullChecking, validate);
  reader->setFeature(xc::XMLUni::fgXercesIdentityConstraintChecking, validate);
  reader->setFeature(xc::XMLUni::fgXercesUseCachedGrammarInParse, validate);
  reader->setProperty(xc::XMLUni::fgXercesSecurityManager, &security);
  reader->setContentHandler(&collector);
  reader->setErrorHandler(&collector);
  reader->setEntityResolver(&collector);
  return reader;
}

// Xerces places attribute errors at the end of the start tag and unresolved IDREFs at the end of
// the document. This moves such a diagnostic to the attribute (or value) its message quotes, when
// that can be found, and attaches the source line for the caret.
class Positions {
 public:
  explicit Positions(std::string_view text) : text_(text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }

  void refine(Diagnostic& d, bool unresolved_reference) const {
    const std::string quoted = quoted_token(d.message);
    if (!quoted.empty()) {
      if (unresolved_reference) {
        move_to(d, text_.find("=\"" + quoted + "\""), 2);
      } else if (d.where.line >= 1 && static_cast<std::size_t>(d.where.line) <= starts_.size()) {
        const std::string_view line = line_text(d.where.line);
        const std::size_t before = std::min<std::size_t>(line.size(), static_cast<std::size_t>(std::max(d.where.column, 1)));
        std::size_t at = line.rfind(" " + quoted + "=", before);
        if (at != std::string_view::npos) ++at;
        else if ((at = line.rfind("\"" + quoted + "\"", before)) != std::string_view::npos) ++at;
        if (at != std::string_view::npos) d.where.column = static_cast<int>(at) + 1;
      }
    }
    if (d.where.line >= 1 && static_cast<std::size_t>(d.where.line) <= starts_.size())
      d.source_line = std::string(line_text(d.where.line));
  }

 private:
  static std::string quoted_token(const std::string& message) {
    const std::size_t open = message.find('\'');
    const std::size_t close = open == std::string::npos ? open : message.find('\'', open + 1);
    return close == std::string::npos ? std::string{} : message.substr(open + 1, close - open - 1);
  }
  std::string_view line_text(int line) const {
    const std::size_t begin = starts_[static_cast<std::size_t>(line - 1)];
    std::size_t end = text_.find('\n', begin);
    if (end == std::string_view::npos) end = text_.size();
    if (end > begin && text_[end - 1] == '\r') --end;
    return text_.substr(begin, end - begin);
  }
  // Points `d` at file offset `offset + skip`, when found.
  void move_to(Diagnostic& d, std::size_t offset, std::size_t skip) const {
    if (offset == std::string_view::npos) return;
    offset += skip;
    const auto line = std::upper_bound(starts_.begin(), starts_.end(), offset) - starts_.begin();
    d.where.line = static_cast<int>(line);
    d.where.column = static_cast<int>(offset - starts_[static_cast<std::size_t>(line - 1)]) + 1;
  }
  std::string_view text_;
  std::vector<std::size_t> starts_;
};

Result<ValidationReport> validate_with_xerces(std::string_view text_in, const std::string& file) {
  const XmlCh id(file);
  xc::SecurityManager security;
  security.setEntityExpansionLimit(10000);  // entity bombs stop here

  // Pass 1: the root element, parsing only as far as it.
  Collector first(file);
  {
    Reader reader = make_reader(first, security, false);
    xc::MemBufInputSource in(reinterpret_cast<const XMLByte*>(text_in.data()), text_in.size(), id.get(), false);
    xc::XMLPScanToken token;
    bool more = reader->parseFirst(in, token);
    while (more && !first.root_seen && first.problems.empty()) more = reader->parseNext(token);
    if (more) reader->parseReset(token);  // stop the scan early; illegal once it has ended
  }
  if (!first.root_seen) {
    if (!first.problems.empty()) return first.problems.front();
    return make_error(Location::text(file, 1, 1), "no root element");
  }
  const SchemaBinding* binding = schema_for_root(first.root_name, first.root_ns);
  if (!binding) {
    std::string known;
    for (const std::string& k : validated_document_kinds()) known += (known.empty() ? "" : ", ") + k;
    return make_error(Location::text(file, 1, 1),
                      "no schema for root element '" + first.root_name + "'" +
                          (first.root_ns.empty() ? "" : " in namespace " + first.root_ns) +
                          "; fapc validates " + known);
  }
  const auto schema = embedded_schemas().find(std::string(binding->schema));
  if (schema == embedded_schemas().end())
    return make_error(Location{file, 0, 0, -1}, "schema " + std::string(binding->schema) + " was not built in");

  // Pass 2: validate against the cached grammar.
  Collector collector(file, binding->schema == "xmt-o.xsd");
  Reader reader = make_reader(collector, security, true);
  const XmlCh schema_id(std::string(binding->schema));
  xc::MemBufInputSource grammar(reinterpret_cast<const XMLByte*>(schema->second.data()),
                                schema->second.size(), schema_id.get(), false);
  if (!reader->loadGrammar(grammar, xc::Grammar::SchemaGrammarType, true) || !collector.problems.empty()) {
    const std::string why = collector.problems.empty() ? "" : ": " + collector.problems.front().message;
    return make_error(Location{file, 0, 0, -1}, "built-in schema " + std::string(binding->schema) + " does not load" + why);
  }
  xc::MemBufInputSource in(reinterpret_cast<const XMLByte*>(text_in.data()), text_in.size(), id.get(), false);
  reader->parse(in);
  const Positions positions(text_in);
  for (std::size_t i = 0; i < collector.problems.size(); ++i)
    positions.refine(collector.problems[i], collector.unresolved_references.count(i) > 0);
  return ValidationReport{std::string(binding->kind), std::string(binding->schema), std::move(collector.problems)};
}

}  // namespace

bool ValidationReport::valid() const {
  for (const Diagnostic& d : problems)
    if (d.severity == Severity::error) return false;
  return true;
}

std::vector<std::string> validated_document_kinds() {
  std::vector<std::string> out;
  for (const SchemaBinding& b : schema_bindings())
    out.push_back(std::string(b.kind) + (b.ns.empty() ? "" : " (" + std::string(b.ns) + ")"));
  return out;
}

Result<ValidationReport> validate_xml(std::string_view text_in, const std::string& file) {
  // The readers' depth limit holds here too: Xerces would take any depth, slowly.
  if (Status depth = xml::check_element_depth(text_in, file); !depth) return depth.error();
  initialise_xerces();
  // Xerces recurses where fapc cannot bound it (its regular-expression matcher, once per item of
  // a long list attribute): it runs on a stack of its own, large enough for any input that
  // passes fapc's size limits.
  std::optional<Result<ValidationReport>> outcome;
  run_on_deep_stack([&] {
    // Xerces reports some failures (unreadable encodings, input that is not XML at all) by
    // throwing; they become an error at the start of the document.
    try {
      outcome.emplace(validate_with_xerces(text_in, file));
    } catch (const xc::XMLException& e) {
      outcome.emplace(make_error(Location::text(file, 1, 1), text(e.getMessage())));
    } catch (const xc::SAXException& e) {
      outcome.emplace(make_error(Location::text(file, 1, 1), text(e.getMessage())));
    }
  });
  return std::move(*outcome);
}

}  // namespace fapc::xmt

// Xerces-C validation: a progressive SAX2 parse finds the root element, then a full parse
// validates against the one cached grammar the root selects. Xerces stays inside this file.
#include "fapc/xml/xml_validation.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>

#include <xercesc/framework/MemBufInputSource.hpp>
#include <xercesc/framework/XMLPScanToken.hpp>
#include <xercesc/framework/XMLValidityCodes.hpp>
#include <xercesc/framework/psvi/PSVIAttribute.hpp>
#include <xercesc/framework/psvi/PSVIAttributeList.hpp>
#include <xercesc/framework/psvi/PSVIHandler.hpp>
#include <xercesc/framework/psvi/XSSimpleTypeDefinition.hpp>
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
#include <xercesc/validators/schema/SchemaSymbols.hpp>

#include "fapc/codec/deep_stack.hpp"
#include "fapc/xml/codes.hpp"
#include "fapc/xml/xml_document.hpp"
#include "schema_registry.hpp"
#include "xml_tag_scan.hpp"

namespace fapc::xml {

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

// Which attribute a problem is about, as Xerces' API says (never its message): the problem is
// moved there from the end of the start tag where Xerces reports it.
struct AttributeTarget {
  std::string name;      // local name
  bool at_value = true;  // point at the value (false: at the name, for an undeclared attribute)
  std::string token;     // within the value: this token (an IDREFS item), or empty for the start
};

// What Xerces' error codes say a problem is: a validity code, or a datatype validator's
// exception code (Xerces reports a value its type rejects in the exception domain).
struct ProblemCode {
  unsigned validity = 0;  // an XMLValid::Codes, 0: none
  bool datatype = false;  // an XMLExcepts::Codes from a datatype validator
};

// Whether a problem reported at the end of a start tag is about one of its attributes.
bool about_an_attribute(const ProblemCode& code) {
  using v = xc::XMLValid;
  if (code.datatype) return true;
  switch (code.validity) {
    case v::AttNotDefined:
    case v::AttNotDefinedForElement:
    case v::DatatypeError:
    case v::DatatypeValidationFailure:
    case v::ProhibitedAttributePresent:
    case v::AttributeNotQualified:
    case v::AttributeNotUnQualified:
    case v::InvalidEmptyAttValue:
    case v::AttrValNotName:
    case v::ReusedIDValue:
    case v::BadEntityRefAttr:
    case v::UnknownEntityRefAttr:
    case v::UnknownNotRefAttr:
    case v::AttrDupToken:
      return true;
    default:
      return false;
  }
}

// Whether a schema type is (derived from) the built-in `name` (ID, IDREF), or a list of it.
bool is_of_type(xc::XSTypeDefinition* type, const XMLCh* name, bool or_list_of_it) {
  if (!type || type->getTypeCategory() != xc::XSTypeDefinition::SIMPLE_TYPE) return false;
  if (type->derivedFrom(xc::SchemaSymbols::fgURI_SCHEMAFORSCHEMA, name)) return true;
  auto* simple = static_cast<xc::XSSimpleTypeDefinition*>(type);
  return or_list_of_it && simple->getVariety() == xc::XSSimpleTypeDefinition::VARIETY_LIST &&
         is_of_type(simple->getItemType(), name, false);
}

// Collects problems with their positions; remembers the root element when asked to. As the PSVI
// handler of the validating pass it learns which attributes of each start tag are invalid, and
// the document's IDs and ID references.
class Collector : public xc::DefaultHandler, public xc::PSVIHandler {
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
  void fatalError(const xc::SAXParseException& e) override { add(Severity::error, e, codes::xml::not_well_formed); }

  // Called after a start tag's attributes are validated: their problems are reported by then, at
  // the end of the start tag, where the locator still is.
  void handleAttributesPSVI(const XMLCh*, const XMLCh*, xc::PSVIAttributeList* list) override {
    std::vector<AttributeTarget> invalid;
    for (XMLSize_t i = 0; list && i < list->getLength(); ++i) {
      xc::PSVIAttribute* attribute = list->getAttributePSVIAtIndex(i);
      if (!attribute) continue;
      const std::string name = text(list->getAttributeNameAtIndex(i));
      if (attribute->getValidity() == xc::PSVIItem::VALIDITY_INVALID)
        invalid.push_back({name, attribute->getAttributeDeclaration() != nullptr, {}});
      xc::XSTypeDefinition* type = attribute->getTypeDefinition();
      const std::string value = text(attribute->getSchemaNormalizedValue());
      if (is_of_type(type, xc::XMLUni::fgIDString, false)) ids_.insert(value);
      if (is_of_type(type, xc::XMLUni::fgIDRefString, true))
        for (std::size_t at = 0; (at = value.find_first_not_of(" \t\r\n", at)) != std::string::npos;) {
          const std::size_t end = std::min(value.find_first_of(" \t\r\n", at), value.size());
          references_.push_back({here(), {name, true, value.substr(at, end - at)}});
          at = end;
        }
    }
    std::vector<std::size_t> about;  // this start tag's problems about an attribute, in order
    const Location end_of_tag = here();
    for (std::size_t k = start_tag_first_; k < problems.size(); ++k)
      if (about_an_attribute(codes_[k]) && problems[k].where.line == end_of_tag.line &&
          problems[k].where.column == end_of_tag.column)
        about.push_back(k);
    // Xerces validates attributes in order, one problem for each invalid one: paired in order
    // when the counts agree; otherwise the problems stay at the end of the start tag.
    if (about.size() == invalid.size())
      for (std::size_t k = 0; k < about.size(); ++k) targets[about[k]] = invalid[k];
    start_tag_first_ = problems.size();
  }
  void handleElementPSVI(const XMLCh*, const XMLCh*, xc::PSVIElement*) override {}

  // Xerces reports each ID reference naming no ID once, at the end of the document. Those
  // problems are replaced by one per such name, in document order, where it is first used, when
  // the references this collector saw account for all of them.
  void place_unresolved_references() {
    std::vector<std::size_t> reported;
    for (std::size_t k = 0; k < problems.size(); ++k)
      if (codes_[k].validity == xc::XMLValid::IDNotDeclared) reported.push_back(k);
    if (reported.empty()) return;
    std::vector<std::pair<Diagnostic, AttributeTarget>> found;
    std::set<std::string> named;
    for (const auto& [where, target] : references_)
      if (!ids_.count(target.token) && named.insert(target.token).second)
        found.push_back({make_error(codes::xml::undeclared_id, where,
                                    "ID attribute '" + target.token + "' is referenced but was never declared"),
                         target});
    if (found.size() != reported.size()) return;
    for (std::size_t k = 0; k < reported.size(); ++k) {
      problems[reported[k]] = found[k].first;
      targets[reported[k]] = found[k].second;
    }
  }

  // Nothing outside the document is ever read: DTDs and entities named by it resolve to nothing.
  // While a built-in schema loads, the schemas it includes are the built-in ones of that name
  // (bml.xsd includes bml-core.xsd): never a file, and never for the document itself.
  xc::InputSource* resolveEntity(const XMLCh*, const XMLCh* system_id) override {
    static const XMLByte nothing[] = "";
    if (serving_schemas && system_id != nullptr) {
      std::string name = text(system_id);
      name = name.substr(name.find_last_of('/') + 1);
      const auto schema = embedded_schemas().find(name);
      if (schema != embedded_schemas().end())
        return new xc::MemBufInputSource(reinterpret_cast<const XMLByte*>(schema->second.data()), schema->second.size(),
                                         system_id, false);
    }
    return new xc::MemBufInputSource(nothing, 0, "", false);
  }
  bool serving_schemas = false;

  bool root_seen = false;
  std::string root_ns, root_name;
  Diagnostics problems;
  std::map<std::size_t, AttributeTarget> targets;  // problem index -> the attribute it is about
  // Set by CodedReader around each report: Xerces' code for the next problem.
  ProblemCode next_code;

 private:
  Location here() const {
    return Location::text(file_, locator_ ? static_cast<int>(locator_->getLineNumber()) : 0,
                          locator_ ? static_cast<int>(locator_->getColumnNumber()) : 0);
  }

  // values and keyTimes of an XMT-Omega animate (their schema type checks only the characters).
  void check_number_lists(const xc::Attributes& attributes) {
    for (XMLSize_t i = 0; i < attributes.getLength(); ++i) {
      const std::string name = text(attributes.getLocalName(i));
      if (name != "values" && name != "keyTimes") continue;
      const std::string value = text(attributes.getValue(i));
      if (is_number_list(value)) continue;
      const std::string shown = value.size() > 40 ? value.substr(0, 40) + "..." : value;
      targets[problems.size()] = {name, false, {}};
      problems.push_back(make_error(codes::xml::not_a_number_list, here(),
                                    "'" + name + "': '" + shown + "' is not a list of numbers separated by ';'"));
      codes_.push_back({});
    }
  }

  void add(Severity severity, const xc::SAXParseException& e, ErrorCode code = codes::xml::not_valid) {
    const Location at =
        Location::text(file_, static_cast<int>(e.getLineNumber()), static_cast<int>(e.getColumnNumber()));
    problems.push_back(severity == Severity::error ? make_error(code, at, text(e.getMessage()))
                                                   : make_warning(at, text(e.getMessage())));
    codes_.push_back(next_code);
  }
  const std::string& file_;
  bool xmto_lists_;
  const xc::Locator* locator_ = nullptr;
  std::vector<ProblemCode> codes_;  // parallel to `problems`
  std::size_t start_tag_first_ = 0;
  std::set<std::string> ids_;
  std::vector<std::pair<Location, AttributeTarget>> references_;  // where each ID reference is
};

// The SAX2 reader, seeing each error's code before the SAX handler gets only its text: the
// collector learns what a problem is without reading its wording.
class CodedReader : public xc::SAX2XMLReaderImpl {
 public:
  explicit CodedReader(Collector& collector) : collector_(collector) {}
  void error(const unsigned int code, const XMLCh* const domain, const xc::XMLErrorReporter::ErrTypes type,
             const XMLCh* const message, const XMLCh* const system_id, const XMLCh* const public_id,
             const XMLFileLoc line, const XMLFileLoc column) override {
    collector_.next_code = {xc::XMLString::equals(domain, xc::XMLUni::fgValidityDomain) ? code : 0,
                            xc::XMLString::equals(domain, xc::XMLUni::fgExceptDomain)};
    xc::SAX2XMLReaderImpl::error(code, domain, type, message, system_id, public_id, line, column);
    collector_.next_code = {};
  }

 private:
  Collector& collector_;
};

struct ReaderDeleter {
  void operator()(xc::SAX2XMLReader* r) const { delete r; }
};
using Reader = std::unique_ptr<xc::SAX2XMLReader, ReaderDeleter>;

Reader make_reader(Collector& collector, xc::SecurityManager& security, bool validate) {
  auto* coded = new CodedReader(collector);
  Reader reader(coded);
  if (validate) coded->setPSVIHandler(&collector);
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
// the document. This moves a diagnostic whose attribute the collector learnt from the API to that
// attribute's name or value in the text, and attaches the source line for the caret.
class Positions {
 public:
  explicit Positions(std::string_view text) : text_(text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }

  void refine(Diagnostic& d, const AttributeTarget* target) {
    if (target && d.where.line >= 1 && static_cast<std::size_t>(d.where.line) <= starts_.size())
      if (const std::optional<std::size_t> at = attribute_offset(offset_of(d.where), *target)) move_to(d, *at);
    if (d.where.line >= 1 && static_cast<std::size_t>(d.where.line) <= starts_.size())
      d.source_line = std::string(line_text(d.where.line));
  }

 private:
  std::size_t offset_of(const Location& where) const {
    const std::size_t line_start = starts_[static_cast<std::size_t>(where.line - 1)];
    return std::min(text_.size(), line_start + static_cast<std::size_t>(std::max(where.column - 1, 0)));
  }
  // In the start tag that ends at or before `end` (where Xerces reports it): the offset of the
  // attribute's name, or of its value (or of a token in it).
  std::optional<std::size_t> attribute_offset(std::size_t end, const AttributeTarget& target) {
    if (!tags_) tags_ = xml::scan_start_tags(text_);
    auto tag = std::lower_bound(tags_->begin(), tags_->end(), end,
                                [](const xml::ScannedTag& t, std::size_t at) { return t.offset < at; });
    if (tag == tags_->begin()) return std::nullopt;
    --tag;
    for (const auto& [written, at] : tag->attributes) {
      const std::size_t colon = written.find(':');
      if ((colon == std::string::npos ? written : written.substr(colon + 1)) != target.name) continue;
      if (!target.at_value) return at;
      const std::size_t quote = text_.find_first_of("\"'", at + written.size());
      if (quote == std::string_view::npos) return std::nullopt;
      if (target.token.empty()) return quote + 1;
      const std::size_t close = text_.find(text_[quote], quote + 1);
      const std::size_t token = text_.substr(0, close).find(target.token, quote + 1);
      return token == std::string_view::npos ? quote + 1 : token;
    }
    return std::nullopt;
  }
  std::string_view line_text(int line) const {
    const std::size_t begin = starts_[static_cast<std::size_t>(line - 1)];
    std::size_t end = text_.find('\n', begin);
    if (end == std::string_view::npos) end = text_.size();
    if (end > begin && text_[end - 1] == '\r') --end;
    return text_.substr(begin, end - begin);
  }
  void move_to(Diagnostic& d, std::size_t offset) const {
    const auto line = std::upper_bound(starts_.begin(), starts_.end(), offset) - starts_.begin();
    d.where.line = static_cast<int>(line);
    d.where.column = static_cast<int>(offset - starts_[static_cast<std::size_t>(line - 1)]) + 1;
  }
  std::string_view text_;
  std::vector<std::size_t> starts_;
  std::optional<std::vector<xml::ScannedTag>> tags_;  // scanned when first needed
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
    return make_error(codes::xml::no_root, Location::text(file, 1, 1), "no root element");
  }
  const SchemaBinding* binding = schema_for_root(first.root_name, first.root_ns);
  if (!binding) {
    std::string known;
    for (const std::string& k : validated_document_kinds()) known += (known.empty() ? "" : ", ") + k;
    return make_error(codes::xml::no_schema, Location::text(file, 1, 1),
                      "no schema for root element '" + first.root_name + "'" +
                          (first.root_ns.empty() ? "" : " in namespace " + first.root_ns) + "; fapc validates " +
                          known);
  }
  const auto schema = embedded_schemas().find(std::string(binding->schema));
  if (schema == embedded_schemas().end())
    return make_error(codes::xml::schema_missing, Location::whole_file(file),
                      "schema " + std::string(binding->schema) + " was not built in");

  // Pass 2: validate against the cached grammar.
  Collector collector(file, binding->schema == "xmt-o.xsd");
  Reader reader = make_reader(collector, security, true);
  const XmlCh schema_id(std::string(binding->schema));
  xc::MemBufInputSource grammar(reinterpret_cast<const XMLByte*>(schema->second.data()), schema->second.size(),
                                schema_id.get(), false);
  collector.serving_schemas = true;
  const bool loaded = reader->loadGrammar(grammar, xc::Grammar::SchemaGrammarType, true) != nullptr;
  collector.serving_schemas = false;
  if (!loaded || !collector.problems.empty()) {
    const std::string why = collector.problems.empty() ? "" : ": " + collector.problems.front().message;
    return make_error(codes::xml::schema_missing, Location::whole_file(file),
                      "built-in schema " + std::string(binding->schema) + " does not load" + why);
  }
  xc::MemBufInputSource in(reinterpret_cast<const XMLByte*>(text_in.data()), text_in.size(), id.get(), false);
  reader->parse(in);
  collector.place_unresolved_references();
  Positions positions(text_in);
  for (std::size_t i = 0; i < collector.problems.size(); ++i) {
    const auto target = collector.targets.find(i);
    positions.refine(collector.problems[i], target == collector.targets.end() ? nullptr : &target->second);
  }
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
  for (const SchemaBinding& b : schema_bindings()) {
    std::string kind = std::string(b.kind) + (b.ns.empty() ? "" : " (" + std::string(b.ns) + ")");
    if (std::find(out.begin(), out.end(), kind) == out.end())
      out.push_back(std::move(kind));  // SMIL-Agent has two roots
  }
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
      outcome.emplace(make_error(codes::xml::not_well_formed, Location::text(file, 1, 1), text(e.getMessage())));
    } catch (const xc::SAXException& e) {
      outcome.emplace(make_error(codes::xml::not_well_formed, Location::text(file, 1, 1), text(e.getMessage())));
    }
  });
  return std::move(*outcome);
}

}  // namespace fapc::xml

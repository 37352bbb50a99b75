// What the FML-APML and APML readers share: the parsed document, the lexicon, the document being
// built and its once-per-name warnings; the root check; the limit on intentions; and the last step,
// drawing the placed intentions and ending the document.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/file_io.hpp"
#include "fapc/intent/intent.hpp"
#include "fapc/xml/once_per_name.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::intent {

class DocumentReader {
 protected:
  DocumentReader(const xml::XmlDocument& doc, const IntentOptions& options, std::string language);

  // The root element, or an error at it when it is not <name>.
  Result<const xmlNode*> root_named(std::string_view name) const;
  // An error (limit_exceeded, at `node`) once more than options.limits.max_runs `what` are
  // counted: checked before each is stored.
  Status count(const xmlNode* node, const char* what);
  // Draws each intention (start and end set) through the lexicon, ends the document at the last
  // end or at `end` (the speech's, from `end_where`), checks the frames and hands the document over.
  Result<IntentDocument> draw_and_finish(std::vector<Intention> intentions, double end, Location end_where);
  static Diagnostic with_code(Diagnostic d, WarningCode code);

  const xml::XmlDocument& doc_;
  const IntentOptions& options_;
  const vocabulary::BehaviourLexicon& lexicon_;
  IntentDocument out_;
  xml::OncePerName once_;

 private:
  std::int64_t counted_ = 0;
};

// Checks the nesting, parses `text` and runs Reader(document, options).run().
template <class Reader>
Result<IntentDocument> read_document(std::string_view text, const std::string& file_name, const IntentOptions& options,
                                     const xml::BlankText& blank_text) {
  if (const Status depth = xml::check_element_depth(text, file_name); !depth) return depth.error();
  Result<xml::XmlDocument> doc = xml::XmlDocument::parse(text, file_name, blank_text);
  if (!doc) return doc.error();
  return Reader(*doc, options).run();
}

template <class Reader>
Result<IntentDocument> load_document(const std::string& path, const IntentOptions& options,
                                     const xml::BlankText& blank_text) {
  const auto source = SourceText::open(path);
  if (!source) return source.error();
  return read_document<Reader>(source->bytes(), path, options, blank_text);
}

}  // namespace fapc::intent

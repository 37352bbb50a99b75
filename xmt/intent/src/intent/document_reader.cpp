#include "intent/document_reader.hpp"

#include <algorithm>

#include "fapc/intent/codes.hpp"
#include "fapc/xml/text.hpp"
#include "intent/realize.hpp"

namespace fapc::intent {

DocumentReader::DocumentReader(const xml::XmlDocument& doc, const IntentOptions& options, std::string language)
    : doc_(doc),
      options_(options),
      lexicon_(options.lexicon != nullptr ? *options.lexicon : vocabulary::bundled_behaviour_lexicon()),
      once_(out_.warnings) {
  out_.language = std::move(language);
}

Result<const xmlNode*> DocumentReader::root_named(std::string_view name) const {
  const xmlNode* root = doc_.root();
  if (root == nullptr)
    return make_error(codes::intent::empty_document, Location{doc_.file(), 1, 1}, "an empty document");
  if (xml::local_name(root) != name)
    return doc_.error(
        codes::intent::wrong_root, root,
        "the root element is <" + std::string(xml::local_name(root)) + ">, not <" + std::string(name) + ">");
  return root;
}

Status DocumentReader::count(const xmlNode* node, const char* what) {
  if (++counted_ <= options_.limits.max_runs) return ok_status();
  return doc_.error(
      codes::limit::runs, node,
      "more than " + std::to_string(options_.limits.max_runs) + " " + what + " (raise the limit with --max-runs)");
}

Result<IntentDocument> DocumentReader::draw_and_finish(std::vector<Intention> intentions, double end,
                                                       Location end_where) {
  for (Intention& i : intentions) {
    realize(i, lexicon_, options_.speech.coarticulation, out_.timeline, once_, out_.warnings);
    if (i.end > end) {
      end = i.end;
      end_where = i.where;
    }
  }
  out_.intentions = std::move(intentions);
  out_.timeline.explicit_end = end;
  out_.timeline.end_source = end_where;
  if (options_.frames.exceeded_by(end)) return frame_budget_error(end, end_where, options_.frames);
  once_.finish();
  for (const Diagnostic& w : doc_.warnings()) out_.warnings.push_back(w);
  return std::move(out_);
}

Diagnostic DocumentReader::with_code(Diagnostic d, WarningCode code) {
  d.code = code.name;
  return d;
}

}  // namespace fapc::intent

// .xml as an input: most BML, FML-APML and APML documents are named .xml, so the root element and
// its namespace say which reader takes the document (docs/bml.md, "Inputs named .xml"). BML, FML,
// XMT-Omega, FML-APML and APML are read by their readers (the last two: docs/intentions.md); any
// other root is refused naming it.
#include "fapc/codec/file_io.hpp"
#include "formats.hpp"
#include "formats/xml_root.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<Loaded> load_xml(const std::string& path, const ConvertOptions& options) {
  std::string language;
  XmlRoot root;
  {
    const auto source = SourceText::open(path, options.limits);
    if (!source) return source.error();
    Result<XmlRoot> found = find_xml_root(source->bytes(), path);
    if (!found) return found.error();
    root = std::move(*found);
    language = xml_language(root);
  }
  if (language.empty()) {
    return make_error(ErrorKind::unsupported, root.where,
                      "an XML document whose root <" + root.name + ">" + (root.ns.empty() ? "" : " (namespace " + root.ns + ")") +
                          " is none fapc reads (bml, fml, XMT-O, fml-apml, apml)");
  }
  const InputFormat* reader = formats().input_named(language);
  if (reader == nullptr) return make_error(ErrorKind::unsupported, root.where, "no reader for " + language);
  Result<Loaded> loaded = reader->load(path, options);
  if (loaded && options.facts) {
    loaded->facts["recognised_by"] = "root <" + root.name + ">" + (root.ns.empty() ? "" : " in " + root.ns);
  }
  return loaded;
}

}  // namespace

// Every reader an .xml goes to (BML, FML, XMT-Omega) lowers a script to a timeline.
InputFormat xml_input() {
  InputFormat format{"xml", {".xml"}, load_xml};
  format.timeline = true;
  return format;
}

}  // namespace fapc::pipeline::builtin

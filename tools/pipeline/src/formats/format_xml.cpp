// .xml as an input: most BML, FML-APML and APML documents are named .xml, so the root element says
// which reader takes the document (docs/bml.md, "Inputs named .xml"): the row whose xml_roots name
// it. Any other root is refused naming it and the roots fapc reads.
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "fapc/pipeline/registry.hpp"
#include "formats/xml_root.hpp"

namespace fapc::pipeline::builtin {

namespace {

// The roots the table's rows take, for the error about any other: "bml, fml, xmt-o".
std::string roots_read() {
  std::string out;
  for (const InputFormat& f : formats().inputs())
    for (const std::string& root : f.xml_roots) out += (out.empty() ? "" : ", ") + root;
  return out;
}

Result<Loaded> load_xml(const std::string& path, const ConvertOptions& options) {
  XmlRoot root;
  {
    const auto source = SourceText::open(path, options.limits);
    if (!source) return source.error();
    Result<XmlRoot> found = find_xml_root(source->bytes(), path);
    if (!found) return found.error();
    root = std::move(*found);
  }
  const InputFormat* reader = formats().input_for_xml_root(lower_case(root.name));
  if (reader == nullptr) {
    return make_error(codes::format::unknown_xml_root, root.where,
                      "an XML document whose root <" + root.name + ">" +
                          (root.ns.empty() ? "" : " (namespace " + root.ns + ")") +
                          " is none fapc reads (roots read: " + roots_read() + ")");
  }
  Result<Loaded> loaded = reader->load(path, options);
  if (loaded && options.facts) {
    json_of(loaded->facts)["recognised_by"] = "root <" + root.name + ">" + (root.ns.empty() ? "" : " in " + root.ns);
  }
  return loaded;
}

}  // namespace

// Every reader an .xml goes to (the rows with xml_roots) lowers a script to a timeline.
InputFormat xml_input() {
  InputFormat format{"xml", {".xml"}, load_xml};
  format.timeline = true;
  return format;
}

}  // namespace fapc::pipeline::builtin

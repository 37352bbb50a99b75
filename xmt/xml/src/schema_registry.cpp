#include "schema_registry.hpp"

namespace fapc::xml {

namespace {

// The namespaces are the schemas' targetNamespace, written here rather than taken from the XMT-A
// writer and the XMT-Omega reader so that validation depends on neither; the tests that validate
// namespaces test (tests/xml/) fails if they ever disagree.
constexpr SchemaBinding kSchemaBindings[] = {
    {"XMT-A", "XMT-A", "urn:mpeg:mpeg4:xmta:schema:2002", "xmt-a.xsd"},
    // Only documents in the XMT-Omega namespace: a schema has one target namespace, and the
    // reader's own checks cover documents without one.
    {"XMT-Omega", "XMT-O", "urn:mpeg:mpeg4:xmto:schema:2002", "xmt-o.xsd"},
    // FML has no namespace; a root fml in one gets the schema's "no declaration" error.
    {"FML", "fml", "", "fml.xsd"},
    // BML (docs/bml.md, "Validation"): one description, bml-core.xsd, in the namespace of each
    // dialect; documents in no namespace (Greta, SEMAINE, SmartBody) and any other take it as is.
    {"BML 1.0", "bml", "http://www.bml-initiative.org/bml/bml-1.0", "bml.xsd"},
    {"BML (Greta)", "bml", "http://www.mindmakers.org/projects/BML", "bml-mindmakers.xsd"},
    {"BML", "bml", "", "bml-core.xsd"},
    // The intention languages (docs/intentions.md, docs/smil.md): no namespace of their own.
    {"FML-APML", "fml-apml", "", "fml-apml.xsd"},
    {"APML", "apml", "", "apml.xsd"},
    {"SMIL-Agent", "par", "", "smil-agent.xsd"},
    {"SMIL-Agent", "seq", "", "smil-agent.xsd"},
};

}  // namespace

const SchemaBinding* schema_for_root(std::string_view local_name, std::string_view ns) {
  for (const SchemaBinding& b : kSchemaBindings)
    if (b.root == local_name && (b.ns.empty() || b.ns == ns)) return &b;
  return nullptr;
}

std::span<const SchemaBinding> schema_bindings() { return kSchemaBindings; }

}  // namespace fapc::xml

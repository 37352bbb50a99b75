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
};

}  // namespace

const SchemaBinding* schema_for_root(std::string_view local_name, std::string_view ns) {
  for (const SchemaBinding& b : kSchemaBindings)
    if (b.root == local_name && (b.ns.empty() || b.ns == ns)) return &b;
  return nullptr;
}

std::span<const SchemaBinding> schema_bindings() { return kSchemaBindings; }

}  // namespace fapc::xml

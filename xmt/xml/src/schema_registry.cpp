#include "schema_registry.hpp"

#include "fapc/xmt/xmta_writer.hpp"
#include "fapc/xmt/xmto.hpp"

namespace fapc::xmt {

namespace {

constexpr SchemaBinding kSchemaBindings[] = {
    {"XMT-A", "XMT-A", kXmtaNamespace, "xmt-a.xsd"},
    // Only documents in the XMT-Omega namespace: a schema has one target namespace, and the
    // reader's own checks cover documents without one.
    {"XMT-Omega", "XMT-O", kXmtoNamespace, "xmt-o.xsd"},
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

}  // namespace fapc::xmt

#include "schema_registry.hpp"

#include "fapc/xmt/xmta_writer.hpp"

namespace fapc::xmt {

namespace {

constexpr SchemaBinding kSchemaBindings[] = {
    {"XMT-A", "XMT-A", kXmtaNamespace, "xmt-a.xsd"},
};

}  // namespace

const SchemaBinding* schema_for_root(std::string_view local_name, std::string_view ns) {
  for (const SchemaBinding& b : kSchemaBindings)
    if (b.root == local_name && (b.ns.empty() || b.ns == ns)) return &b;
  return nullptr;
}

std::span<const SchemaBinding> schema_bindings() { return kSchemaBindings; }

}  // namespace fapc::xmt

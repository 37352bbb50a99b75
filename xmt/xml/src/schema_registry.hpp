// Which schema validates which document, by root element. To add a document kind: put its .xsd
// in docs/schemas/ and add a row to kSchemaBindings (schema_registry.cpp).
#pragma once

#include <map>
#include <span>
#include <string>
#include <string_view>

namespace fapc::xmt {

struct SchemaBinding {
  std::string_view kind;    // shown to users
  std::string_view root;    // local name of the root element
  std::string_view ns;      // its namespace; empty: any (the schema then decides)
  std::string_view schema;  // file name under docs/schemas/
};

// The binding for a root element, or nullptr.
const SchemaBinding* schema_for_root(std::string_view local_name, std::string_view ns);
std::span<const SchemaBinding> schema_bindings();

// Generated from docs/schemas/*.xsd (cmake/EmbedSchemas.cmake): file name -> schema text.
const std::map<std::string, std::string_view>& embedded_schemas();

}  // namespace fapc::xmt

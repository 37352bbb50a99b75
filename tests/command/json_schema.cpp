#include "json_schema.hpp"

#include <set>

#include "support/test_support.hpp"

namespace fapc::test {

namespace {

bool has_type(const nlohmann::json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "integer") return value.is_number_integer();
  if (type == "number") return value.is_number();
  if (type == "boolean") return value.is_boolean();
  if (type == "null") return value.is_null();
  return false;
}

const std::set<std::string> kKnown = {
    "$schema", "$id",        "title",    "description",          "$defs", "type",    "enum",
    "const",   "properties", "required", "additionalProperties", "items", "minimum", "maximum",
    "oneOf",   "$ref"};

}  // namespace

const nlohmann::json& SchemaFolder::load(const std::string& file) {
  for (const auto& [name, schema] : loaded_)
    if (name == file) return schema;
  loaded_.emplace_back(file, nlohmann::json::parse(read_text(folder_ + "/" + file)));
  return loaded_.back().second;
}

std::vector<std::string> SchemaFolder::validate(const nlohmann::json& document, const std::string& schema) {
  std::vector<std::string> problems;
  check(document, load(schema), schema, "$", problems);
  return problems;
}

void SchemaFolder::check(const nlohmann::json& value, const nlohmann::json& schema, const std::string& file,
                         const std::string& where, std::vector<std::string>& problems) {
  const auto problem = [&](const std::string& what) { problems.push_back(where + ": " + what); };
  for (const auto& [keyword, unused] : schema.items())
    if (!kKnown.count(keyword)) problem("schema keyword '" + keyword + "' is not implemented by this validator");
  if (schema.contains("$ref")) {
    const std::string ref = schema["$ref"];
    if (ref.starts_with("#/$defs/")) {
      check(value, load(file)["$defs"][ref.substr(8)], file, where, problems);
    } else {
      check(value, load(ref), ref, where, problems);
    }
    return;
  }
  if (schema.contains("type")) {
    const std::vector<std::string> types = schema["type"].is_array()
                                               ? schema["type"].get<std::vector<std::string>>()
                                               : std::vector<std::string>{schema["type"].get<std::string>()};
    bool any = false;
    for (const std::string& type : types) any = any || has_type(value, type);
    if (!any) return problem("expected " + schema["type"].dump() + ", found " + value.dump());
  }
  if (schema.contains("enum")) {
    bool any = false;
    for (const auto& allowed : schema["enum"]) any = any || allowed == value;
    if (!any) problem(value.dump() + " is not one of " + schema["enum"].dump());
  }
  if (schema.contains("const") && schema["const"] != value) problem("expected " + schema["const"].dump());
  if (value.is_number()) {
    if (schema.contains("minimum") && value.get<double>() < schema["minimum"].get<double>())
      problem(value.dump() + " is below " + schema["minimum"].dump());
    if (schema.contains("maximum") && value.get<double>() > schema["maximum"].get<double>())
      problem(value.dump() + " is above " + schema["maximum"].dump());
  }
  if (schema.contains("oneOf")) {
    int matching = 0;
    for (const auto& option : schema["oneOf"]) {
      std::vector<std::string> mine;
      check(value, option, file, where, mine);
      matching += mine.empty();
    }
    if (matching != 1) problem("matches " + std::to_string(matching) + " of the oneOf schemas, not one");
  }
  if (value.is_object()) {
    for (const auto& name : schema.value("required", nlohmann::json::array()))
      if (!value.contains(name.get<std::string>())) problem("missing required key '" + name.get<std::string>() + "'");
    const nlohmann::json properties = schema.value("properties", nlohmann::json::object());
    for (const auto& [key, item] : value.items()) {
      if (properties.contains(key)) {
        check(item, properties[key], file, where + "." + key, problems);
      } else if (schema.contains("additionalProperties")) {
        const auto& extra = schema["additionalProperties"];
        if (extra.is_boolean()) {
          if (!extra.get<bool>()) problem("key '" + key + "' is not in the schema");
        } else {
          check(item, extra, file, where + "." + key, problems);
        }
      }
    }
  }
  if (value.is_array() && schema.contains("items"))
    for (std::size_t k = 0; k < value.size(); ++k)
      check(value[k], schema["items"], file, where + "[" + std::to_string(k) + "]", problems);
}

}  // namespace fapc::test

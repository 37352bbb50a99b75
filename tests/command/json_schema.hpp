// A validator for the part of JSON Schema (2020-12) that docs/json/*.schema.json use: type, enum,
// const, properties, required, additionalProperties, items, minimum, maximum, oneOf and $ref (to
// another file of the folder or to "#/$defs/NAME"). A keyword outside that list is reported as an
// error, so a schema cannot rely on a check this validator would skip.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fapc::test {

class SchemaFolder {
 public:
  explicit SchemaFolder(std::string folder) : folder_(std::move(folder)) {}
  // Every way `document` breaks the schema in file `schema` ("$.files[0].ok: expected boolean").
  std::vector<std::string> validate(const nlohmann::json& document, const std::string& schema);

 private:
  const nlohmann::json& load(const std::string& file);
  void check(const nlohmann::json& value, const nlohmann::json& schema, const std::string& file,
             const std::string& where, std::vector<std::string>& problems);

  std::string folder_;
  std::vector<std::pair<std::string, nlohmann::json>> loaded_;
};

}  // namespace fapc::test

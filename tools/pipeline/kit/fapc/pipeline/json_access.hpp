// The JSON library's value inside a JsonValue, for the code built with fapc (its program, the
// pipeline's own sources, the tests). Not installed: an installed fapc's public headers need only
// the C++ standard library (docs/architecture.md, "Public headers and kits").
#pragma once

#include <nlohmann/json.hpp>

#include "fapc/pipeline/json_value.hpp"

namespace fapc::pipeline {

struct JsonValue::Held {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
};

inline nlohmann::ordered_json& json_of(JsonValue& value) { return value.held().json; }
inline const nlohmann::ordered_json& json_of(const JsonValue& value) { return value.held().json; }

inline JsonValue json_value(nlohmann::ordered_json json) {
  JsonValue out;
  json_of(out) = std::move(json);
  return out;
}

}  // namespace fapc::pipeline

#include "fapc/pipeline/json_access.hpp"

namespace fapc::pipeline {

JsonValue::JsonValue() : held_(std::make_unique<Held>()) {}
JsonValue::JsonValue(const JsonValue& other) : held_(std::make_unique<Held>(other.held())) {}
JsonValue::JsonValue(JsonValue&& other) noexcept = default;
JsonValue& JsonValue::operator=(const JsonValue& other) {
  if (this != &other) held() = other.held();
  return *this;
}
JsonValue& JsonValue::operator=(JsonValue&& other) noexcept = default;
JsonValue::~JsonValue() = default;

// A moved-from value reads as an empty object, and is one again when written.
JsonValue::Held& JsonValue::held() {
  if (!held_) held_ = std::make_unique<Held>();
  return *held_;
}

const JsonValue::Held& JsonValue::held() const {
  static const Held kEmpty;
  return held_ ? *held_ : kEmpty;
}

bool JsonValue::empty() const { return held().json.empty(); }

std::string JsonValue::dump(int indent) const { return held().json.dump(indent); }

}  // namespace fapc::pipeline

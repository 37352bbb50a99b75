// A JSON value the pipeline made (a reader's facts about its format, the `info --json` document, a
// merged batch report: docs/json.md), held behind the library so that the public headers need no
// JSON library: a user of the installed library takes it as text. Code built with fapc reaches
// the value itself through the pipeline's kit (fapc/pipeline/json_access.hpp, not installed).
#pragma once

#include <memory>
#include <string>

namespace fapc::pipeline {

class JsonValue {
 public:
  JsonValue();  // an empty object, {}
  JsonValue(const JsonValue& other);
  JsonValue(JsonValue&& other) noexcept;
  JsonValue& operator=(const JsonValue& other);
  JsonValue& operator=(JsonValue&& other) noexcept;
  ~JsonValue();

  // Null, or an object or array with no member.
  bool empty() const;
  // The text: on one line (indent < 0), or `indent` spaces a level as the program prints it.
  std::string dump(int indent = -1) const;

  struct Held;  // the value itself (json_access.hpp)
  Held& held();
  const Held& held() const;

 private:
  std::unique_ptr<Held> held_;  // never null but after a move
};

}  // namespace fapc::pipeline

// Element names stored once: a reader that remembers the name of each of a million elements keeps
// a small number per element instead of a string (a document uses a handful of names).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace fapc::xml {

class NameTable {
 public:
  // The number of `name`, added when new.
  std::uint32_t number(std::string_view name) {
    if (const auto found = numbers_.find(std::string(name)); found != numbers_.end()) return found->second;
    const auto added = static_cast<std::uint32_t>(names_.size());
    names_.emplace_back(name);
    numbers_.emplace(names_.back(), added);
    return added;
  }
  const std::string& name(std::uint32_t number) const { return names_[number]; }

 private:
  std::vector<std::string> names_;
  std::unordered_map<std::string, std::uint32_t> numbers_;
};

}  // namespace fapc::xml

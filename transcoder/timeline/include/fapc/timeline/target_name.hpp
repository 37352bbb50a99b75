// A clip's target, interned: a timeline of a million clips names a few dozen parameters, and a
// std::string per clip cost 32 bytes plus, for names of 16 characters or more ("close_t_l_eyelid"),
// a heap copy. Equal names share one copy kept for the life of the process (the table FileName
// interns paths in), so a TargetName is one pointer. Reads like a const std::string.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "fapc/codec/file_name.hpp"

namespace fapc::timeline {

class TargetName {
 public:
  TargetName() = default;                                                 // the empty name
  TargetName(std::string_view name) : name_(intern(name)) {}              // NOLINT: a name is a target
  TargetName(const std::string& name) : name_(std::string_view(name)) {}  // NOLINT
  TargetName(const char* name) : name_(std::string_view(name)) {}         // NOLINT

  const std::string& str() const { return name_.str(); }
  operator const std::string&() const { return str(); }  // NOLINT: reads as the name
  operator std::string_view() const { return str(); }    // NOLINT
  bool empty() const { return name_.empty(); }
  std::size_t size() const { return str().size(); }
  const char* c_str() const { return str().c_str(); }

  friend bool operator==(const TargetName& a, const TargetName& b) { return a.name_ == b.name_; }
  friend bool operator==(const TargetName& a, const std::string& b) { return a.str() == b; }
  friend bool operator==(const TargetName& a, std::string_view b) { return a.str() == b; }
  friend bool operator==(const TargetName& a, const char* b) { return a.str() == b; }
  friend bool operator<(const TargetName& a, const TargetName& b) { return a.str() < b.str(); }

  friend std::string operator+(const TargetName& a, const std::string& b) { return a.str() + b; }
  friend std::string operator+(const std::string& a, const TargetName& b) { return a + b.str(); }
  friend std::string operator+(const TargetName& a, const char* b) { return a.str() + b; }
  friend std::string operator+(const char* a, const TargetName& b) { return a + b.str(); }

 private:
  // A front end names a few targets in turn: the ones met lately are found without the table.
  static FileName intern(std::string_view name);
  FileName name_;  // the interning: one copy per distinct string, never freed
};

std::ostream& operator<<(std::ostream& out, const TargetName& name);

}  // namespace fapc::timeline

// Until the tree names the model fapc::timeline::..., the names are seen from fapc as before.
namespace fapc {
using namespace timeline;
}  // namespace fapc

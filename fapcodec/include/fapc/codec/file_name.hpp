// The file a Location names, shared: every position in a file names it through one pointer to one
// interned copy of its path. A script of a million elements has millions of positions (in its
// parse tree, its schedule, its clips); a std::string each cost 32 bytes plus a heap copy of the
// path. Reads like a const std::string.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>

namespace fapc {

class FileName {
 public:
  FileName() = default;                                                    // the empty name: no file
  FileName(std::string_view name);                                         // NOLINT: a path is a file name
  FileName(const std::string& name) : FileName(std::string_view(name)) {}  // NOLINT
  FileName(const char* name) : FileName(std::string_view(name)) {}         // NOLINT

  const std::string& str() const { return name_ ? *name_ : no_name(); }
  operator const std::string&() const { return str(); }  // NOLINT: reads as the path
  operator std::string_view() const { return str(); }    // NOLINT
  bool empty() const { return !name_; }
  std::size_t size() const { return str().size(); }
  const char* c_str() const { return str().c_str(); }

  // One interned copy per path: equal names share it.
  friend bool operator==(const FileName& a, const FileName& b) { return a.name_ == b.name_; }
  friend bool operator==(const FileName& a, const std::string& b) { return a.str() == b; }
  friend bool operator==(const FileName& a, std::string_view b) { return a.str() == b; }
  friend bool operator==(const FileName& a, const char* b) { return a.str() == b; }

  friend std::string operator+(const FileName& a, const std::string& b) { return a.str() + b; }
  friend std::string operator+(const std::string& a, const FileName& b) { return a + b.str(); }
  friend std::string operator+(const FileName& a, const char* b) { return a.str() + b; }
  friend std::string operator+(const char* a, const FileName& b) { return a + b.str(); }
  friend std::string operator+(const FileName& a, char b) { return a.str() + b; }

 private:
  static const std::string& no_name() {
    static const std::string empty;
    return empty;
  }
  const std::string* name_ = nullptr;  // interned for the life of the process, never freed; null: none
};

std::ostream& operator<<(std::ostream& out, const FileName& name);

}  // namespace fapc

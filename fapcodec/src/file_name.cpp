// Interning file names: a process meets few distinct paths (the inputs and their includes), each
// kept once for the life of the process, so a FileName is a plain pointer that never dangles.
#include "fapc/codec/file_name.hpp"

#include <mutex>
#include <ostream>
#include <unordered_set>

namespace fapc {

namespace {

struct Interned {
  std::mutex lock;
  std::unordered_set<std::string> names;  // nodes never move: pointers to them stay valid
};

Interned& interned() {
  static Interned* table = new Interned;  // never destroyed: FileNames may outlive static destructors
  return *table;
}

}  // namespace

FileName::FileName(std::string_view name) {
  if (name.empty()) return;
  // Front ends name one file over and over: the last name this thread interned is the usual answer.
  thread_local const std::string* last = nullptr;
  if (last && *last == name) {
    name_ = last;
    return;
  }
  Interned& table = interned();
  const std::lock_guard<std::mutex> hold(table.lock);
  name_ = &*table.names.emplace(name).first;
  last = name_;
}

std::ostream& operator<<(std::ostream& out, const FileName& name) { return out << name.str(); }

}  // namespace fapc

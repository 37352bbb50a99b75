#include "fapc/timeline/target_name.hpp"

#include <array>
#include <ostream>

namespace fapc::timeline {

FileName TargetName::intern(std::string_view name) {
  constexpr std::size_t kRecent = 8;
  thread_local std::array<FileName, kRecent> recent;
  thread_local std::size_t next = 0;
  for (const FileName& known : recent)
    if (!known.empty() && std::string_view(known) == name) return known;
  FileName interned(name);
  recent[next] = interned;
  next = (next + 1) % kRecent;
  return interned;
}

std::ostream& operator<<(std::ostream& out, const TargetName& name) { return out << name.str(); }

}  // namespace fapc::timeline

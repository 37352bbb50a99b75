#include "xmto/once_per_name.hpp"

#include <algorithm>
#include <vector>

namespace fapc::xmt {

void OncePerName::report(const std::string& key, Diagnostic warning) {
  ++entries_.try_emplace(key, Entry{entries_.size(), std::move(warning), 0}).first->second.count;
}

Diagnostics OncePerName::take() {
  std::vector<Entry*> ordered;
  for (auto& [key, entry] : entries_) ordered.push_back(&entry);
  std::sort(ordered.begin(), ordered.end(), [](const Entry* a, const Entry* b) { return a->order < b->order; });
  Diagnostics out;
  for (Entry* entry : ordered) {
    if (entry->count > 1)
      entry->warning.message += " (" + std::to_string(entry->count) + " times; first here)";
    out.push_back(std::move(entry->warning));
  }
  entries_.clear();
  return out;
}

}  // namespace fapc::xmt

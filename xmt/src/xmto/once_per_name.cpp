#include "xmto/once_per_name.hpp"

namespace fapc::xmt {

void OncePerName::report(const std::string& key, Diagnostic warning) {
  const auto [seen, fresh] = seen_.try_emplace(key, Seen{out_.size(), 0});
  if (fresh) out_.push_back(std::move(warning));
  ++seen->second.count;
}

void OncePerName::finish() {
  for (auto& [key, seen] : seen_) {
    if (seen.count > 1) {
      out_[seen.index].message += " (" + std::to_string(seen.count) + " times; first here)";
      seen.count = 1;
    }
  }
}

}  // namespace fapc::xmt

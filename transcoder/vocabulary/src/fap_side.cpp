#include "fapc/vocabulary/fap_side.hpp"

#include <string>
#include <string_view>

#include "fapc/codec/fap_table.hpp"

namespace fapc::vocabulary {
namespace {

// The side token of a standard name: one of its '_'-separated words.
Side side_of_name(std::string_view name) {
  for (std::size_t start = 0; start <= name.size();) {
    const std::size_t end = std::min(name.find('_', start), name.size());
    const std::string_view word = name.substr(start, end - start);
    if (word == "l" || word == "lm") return Side::left;
    if (word == "r" || word == "rm") return Side::right;
    start = end + 1;
  }
  return Side::middle;
}

}  // namespace

Side fap_side(int fap) {
  const FapInfo* info = find_fap(fap);
  return info ? side_of_name(info->name) : Side::middle;
}

int mirror_fap(int fap) {
  const FapInfo* info = find_fap(fap);
  const Side side = fap_side(fap);
  if (!info || side == Side::middle) return fap;
  // The partner's name swaps the side word; paired FAPs are neighbours in the table.
  for (int other : {fap - 1, fap + 1}) {
    const FapInfo* candidate = find_fap(other);
    if (!candidate || fap_side(other) == side || fap_side(other) == Side::middle) continue;
    std::string a(info->name), b(candidate->name);
    for (std::string* s : {&a, &b}) {
      for (const char* from : {"_lm", "_rm", "_l_", "_r_", "_l", "_r"}) {
        const std::size_t at = s->find(from);
        if (at != std::string::npos) {
          s->replace(at, std::string_view(from).size(), "_S" + std::string(from + 2));
          break;
        }
      }
    }
    if (a == b) return other;
  }
  return fap;
}

}  // namespace fapc::vocabulary

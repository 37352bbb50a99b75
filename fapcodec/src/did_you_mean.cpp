#include "fapc/codec/did_you_mean.hpp"

#include <algorithm>
#include <utility>

namespace fapc {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates,
                                       std::size_t how_many, std::size_t max_distance) {
  std::vector<std::pair<std::size_t, const std::string*>> scored;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(name, candidate);
    if (max_distance == 0 || distance <= max_distance) scored.emplace_back(distance, &candidate);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> best;
  for (const auto& [distance, candidate] : scored) {
    if (best.size() == how_many) break;
    if (std::find(best.begin(), best.end(), *candidate) == best.end()) best.push_back(*candidate);
  }
  return best;
}

std::size_t plausible_distance(std::string_view name) {
  return name.size() < 3 ? 1 : std::clamp<std::size_t>(name.size() / 3, 2, 3);
}

std::string or_list(const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) list += i + 1 == names.size() ? " or " : ", ";
    list += names[i];
  }
  return list;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates, std::size_t how_many) {
  const std::vector<std::string> best = closest_names(name, candidates, how_many, plausible_distance(name));
  return best.empty() ? std::string() : "; did you mean " + or_list(best) + "?";
}

}  // namespace fapc

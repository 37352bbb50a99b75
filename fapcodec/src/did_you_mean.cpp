#include "fapc/codec/did_you_mean.hpp"

#include <algorithm>
#include <utility>

namespace fapc {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  return bounded_edit_distance(a, b, std::max(a.size(), b.size()));
}

std::size_t bounded_edit_distance(std::string_view a, std::string_view b, std::size_t bound) {
  if (a.size() < b.size()) std::swap(a, b);           // b is the shorter: one row of it
  if (a.size() - b.size() > bound) return bound + 1;  // that many insertions at least
  // Only cells within `bound` of the diagonal can hold a distance <= bound; the others are
  // taken as bound + 1. A row whose every cell passes the bound ends the search.
  const std::size_t over = bound + 1;
  std::vector<std::size_t> row(b.size() + 1, over);
  for (std::size_t j = 0; j <= std::min(b.size(), bound); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    const std::size_t from = i > bound ? i - bound : 1;
    const std::size_t to = std::min(b.size(), i + bound);
    std::size_t diagonal = row[from - 1];
    row[from - 1] = from == 1 && i <= bound ? i : over;
    std::size_t best = row[from - 1];
    for (std::size_t j = from; j <= to; ++j) {
      const std::size_t above = row[j];
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({above + 1, row[j - 1] + 1, diagonal + cost, over});
      diagonal = above;
      best = std::min(best, row[j]);
    }
    if (best > bound) return over;
  }
  return std::min(row[b.size()], over);
}

std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates,
                                       std::size_t how_many, std::size_t max_distance) {
  // "Keep all" still bounds the search by the longest candidate: a name no longer than it is
  // within that many edits of every candidate (all are kept, as before); a longer one is compared
  // only with candidates within that many characters of its length, so a name of a million
  // letters costs no more than one of the longest candidate's length.
  std::size_t bound = max_distance;
  if (bound == 0)
    for (const std::string& candidate : candidates) bound = std::max(bound, candidate.size());
  std::vector<std::pair<std::size_t, const std::string*>> scored;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = bounded_edit_distance(name, candidate, bound);
    if (distance <= bound) scored.emplace_back(distance, &candidate);
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

std::string quoted_name(std::string_view name) {
  if (name.size() <= kQuotedNameLength) return "'" + std::string(name) + "'";
  return "'" + std::string(name.substr(0, kQuotedNameLength)) + "...' (" + std::to_string(name.size()) + " characters)";
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates, std::size_t how_many) {
  const std::vector<std::string> best = closest_names(name, candidates, how_many, plausible_distance(name));
  return best.empty() ? std::string() : "; did you mean " + or_list(best) + "?";
}

}  // namespace fapc

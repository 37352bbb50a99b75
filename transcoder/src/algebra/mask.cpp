// Overlap masks written as text: group names, FAP names or numbers, ranges, exclusions.
#include <cctype>
#include <charconv>

#include "fapc/codec/fap_table.hpp"
#include "fapc/transcoder/algebra.hpp"
#include "fapc/transcoder/codes.hpp"

namespace fapc::algebra {
namespace {

std::vector<int> range(int first, int last) {
  std::vector<int> faps;
  for (int f = first; f <= last; ++f) faps.push_back(f);
  return faps;
}

std::vector<int> joined(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::optional<int> number(std::string_view text) {
  int value = 0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (status != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

// The standard FAP groups (docs/fap-table.md section 3) under short names, plus "mouth" (both lip
// groups) and "all".
const std::vector<std::pair<std::string_view, std::vector<int>>>& mask_group_names() {
  static const std::vector<std::pair<std::string_view, std::vector<int>>> names{
      {"jaw", range(3, 18)},
      {"lips", range(3, 18)},
      {"eyes", range(19, 30)},
      {"brows", range(31, 38)},
      {"cheeks", range(39, 42)},
      {"tongue", range(43, 47)},
      {"head", range(48, 50)},
      {"outer_lips", range(51, 60)},
      {"nose", range(61, 64)},
      {"ears", range(65, 68)},
      {"mouth", joined(range(3, 18), range(51, 60))},
      {"all", range(3, 68)},
  };
  return names;
}

Result<Mask> parse_mask(std::string_view text) {
  Mask mask;
  std::size_t at = 0;
  bool any = false;
  while (at < text.size()) {
    while (at < text.size() && (text[at] == ',' || std::isspace(static_cast<unsigned char>(text[at])))) ++at;
    if (at >= text.size()) break;
    const std::size_t start = at;
    while (at < text.size() && text[at] != ',' && !std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    std::string_view item = text.substr(start, at - start);
    const auto fail = [&](ErrorCode code, const std::string& why) {
      return make_error(code, Location{"", 0, static_cast<int>(start), -1}, why);
    };
    const bool remove = item.starts_with('!');
    if (remove) item.remove_prefix(1);
    std::vector<int> faps;
    if (const auto dash = item.find('-'); dash != std::string_view::npos && dash > 0) {
      const auto first = number(item.substr(0, dash));
      const auto last = number(item.substr(dash + 1));
      if (!first || !last || *first < 3 || *last > 68 || *first > *last) {
        return fail(codes::algebra::bad_mask, "'" + std::string(item) + "' is not a FAP range within 3-68");
      }
      faps = range(*first, *last);
    } else if (const FapInfo* fap = find_fap_by_name_or_number(item)) {
      if (fap->number < 3)
        return fail(codes::algebra::bad_mask,
                    "FAP " + std::to_string(fap->number) + " is not part of a facial state (3-68)");
      faps = {fap->number};
    } else {
      for (const auto& [name, members] : mask_group_names()) {
        if (name == item) faps = members;
      }
      if (faps.empty()) {
        return fail(codes::algebra::bad_mask,
                    "unknown mask item '" + std::string(item) +
                        "' (a group: jaw, lips, eyes, brows, cheeks, tongue, head, outer_lips, nose, "
                        "ears, mouth, all; a FAP name or number; or a range like 19-30)");
      }
    }
    for (const int f : faps) {
      if (remove) {
        mask.bits.reset(static_cast<std::size_t>(f - 3));
      } else {
        mask.set(f);
      }
    }
    any = true;
  }
  if (!any) return make_error(codes::algebra::empty_mask, Location{}, "an empty mask covers nothing");
  return mask;
}

}  // namespace fapc::algebra

#include "xmto/attribute_target.hpp"

#include <array>
#include <utility>

#include "fapc/codec/fap_table.hpp"
#include "fapc/transcoder/profile.hpp"

namespace fapc::xmt {
namespace {

// BIFS FAP field names (docs/fap-table.md section 5) that are no ISO/IEC 14496-2 name: unambiguous.
constexpr std::array<std::pair<std::string_view, int>, 4> kBifsOnlyNames{{
    {"stretch_l_corner", 6},
    {"stretch_r_corner", 7},
    {"lower_b_lip_lm", 10},
    {"lower_b_lip_rm", 11},
}};

// 14496-2 names that BIFS gives to another FAP: read as 14496-2, with a warning.
constexpr std::array<std::pair<std::string_view, int>, 2> kAmbiguousNames{{
    {"stretch_l_cornerlip", 53},
    {"stretch_r_cornerlip", 54},
}};

}  // namespace

std::optional<AttributeTarget> resolve_attribute_name(std::string_view name, std::string& error) {
  if (name.empty()) {
    error = "attributeName is empty";
    return std::nullopt;
  }
  if (const auto weight = weight_target(name)) {
    const std::string_view label = weight->fap == 1 ? viseme_name(weight->number) : expression_name(weight->number);
    return AttributeTarget{std::string(weight->fap == 1 ? "viseme." : "expression.") + std::string(label), {}};
  }
  if (name.starts_with("viseme.") || name.starts_with("expression.")) {
    const bool viseme = name.starts_with("viseme.");
    error = "unknown " + std::string(viseme ? "viseme" : "expression") + " '" +
            std::string(name.substr(name.find('.') + 1)) + "'; the names are";
    for (int number = 0; number < (viseme ? 15 : 7); ++number)
      error += ' ' + std::string(viseme ? viseme_name(number) : expression_name(number));
    return std::nullopt;
  }
  for (const auto& [bifs, fap] : kBifsOnlyNames) {
    if (name == bifs) return AttributeTarget{std::string(find_fap(fap)->name), {}};
  }
  const FapInfo* fap = find_fap_by_name_or_number(name);
  if (!fap) {
    error = unknown_fap_message(name) +
            " (attributeName takes a FAP name or number 3..68, "
            "viseme.<name> or expression.<name>)";
    return std::nullopt;
  }
  if (fap->number <= 2) {
    error = "FAP " + std::to_string(fap->number) + " (" + std::string(fap->name) +
            ") is not one value: animate viseme.<name> or expression.<name> weights instead";
    return std::nullopt;
  }
  AttributeTarget out{std::string(fap->name), {}};
  for (const auto& [ambiguous, bifs_fap] : kAmbiguousNames) {
    if (name == ambiguous) {
      out.warning = "'" + std::string(name) + "' is read as FAP " + std::to_string(fap->number) +
                    " (ISO/IEC 14496-2 naming); in BIFS naming it is FAP " + std::to_string(bifs_fap) +
                    ": write the number to say which";
    }
  }
  return out;
}

}  // namespace fapc::xmt

#include "fapc/transcoder/profile.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "fapc/codec/fap_table.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/transcoder/codes.hpp"

namespace fapc {
namespace {

bool same_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

struct Field {
  std::string_view text;
  int column = 0;  // 1-based
};

std::vector<Field> split_fields(std::string_view line) {
  std::vector<Field> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i >= line.size() || line[i] == '#') break;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    fields.push_back(Field{line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return fields;
}

}  // namespace

std::optional<WeightTarget> weight_target(std::string_view target) {
  const bool viseme = target.starts_with("viseme.");
  if (!viseme && !target.starts_with("expression.")) return std::nullopt;
  const std::string_view name = target.substr(target.find('.') + 1);
  for (int number = 0; number < (viseme ? 15 : 7); ++number) {
    if (same_ignoring_case(name, viseme ? viseme_name(number) : expression_name(number))) {
      return WeightTarget{viseme ? 1 : 2, number};
    }
  }
  return std::nullopt;
}

Result<Profile> parse_profile(std::string_view text, const std::string& file_name) {
  Profile profile;
  profile.name = file_name;
  int line_number = 0;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
    ++line_number;
    if (line.ends_with('\r')) line.remove_suffix(1);
    const std::vector<Field> fields = split_fields(line);
    if (fields.empty()) continue;
    const auto error = [&](ErrorCode code, const Field& at, std::string message) {
      return make_error(code, Location::text(file_name, line_number, at.column), std::move(message), std::string(line));
    };
    if (fields.size() != 3) {
      return error(codes::profile::field_count, fields.size() > 3 ? fields[3] : fields.back(),
                   "expected 'name fap scale', found " + std::to_string(fields.size()) + " fields");
    }
    const FapInfo* fap = find_fap_by_name_or_number(fields[1].text);
    if (fap == nullptr || fap->number <= 2) {
      return error(codes::profile::bad_fap, fields[1],
                   fap ? "FAP 1 and 2 are not scalar parameters; use viseme.<name> or "
                         "expression.<name> targets"
                       : unknown_fap_message(fields[1].text));
    }
    double scale = 0;
    const Field& scale_field = fields[2];
    const char* end = scale_field.text.data() + scale_field.text.size();
    const auto [stop, status] = std::from_chars(scale_field.text.data(), end, scale);
    if (status != std::errc{} || stop != end || !std::isfinite(scale)) {
      return error(codes::profile::bad_scale, scale_field,
                   "the scale '" + std::string(scale_field.text) + "' is not a number");
    }
    if (find_fap_by_name_or_number(fields[0].text) != nullptr) {
      return error(codes::profile::standard_name, fields[0],
                   "'" + std::string(fields[0].text) + "' is a standard FAP name; a profile maps other names");
    }
    profile.parameters[std::string(fields[0].text)].push_back(FapContribution{fap->number, scale});
  }
  return profile;
}

Result<Profile> load_profile(const std::string& path) {
  Result<std::string> bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return parse_profile(*bytes, path);
}

std::vector<FapContribution> resolve_target(std::string_view target, const Profile& profile) {
  if (const FapInfo* fap = find_fap_by_name_or_number(target); fap != nullptr && fap->number > 2) {
    return {FapContribution{fap->number, 1}};
  }
  if (const std::optional<WeightTarget> weight = weight_target(target)) {
    return {FapContribution{weight->fap, 1}};
  }
  if (const auto found = profile.parameters.find(target); found != profile.parameters.end()) {
    return found->second;
  }
  return {};
}

std::string unknown_parameter_message(std::string_view name, const Profile& profile) {
  std::vector<std::string> candidates;
  for (const auto& [parameter, contributions] : profile.parameters) candidates.push_back(parameter);
  for (const FapInfo& fap : fap_table()) {
    // FAP 1 and 2 are reached through viseme.<name> / expression.<name>, not by their own names.
    if (fap.number > 2) candidates.emplace_back(fap.name);
  }
  const std::vector<std::string> best = closest_names(name, candidates, 3);
  std::string message = "unknown animation parameter " + quoted_name(name);
  for (std::size_t i = 0; i < best.size(); ++i) message += (i == 0 ? "; did you mean " : ", ") + best[i];
  return message + (best.empty() ? "" : "?");
}

}  // namespace fapc

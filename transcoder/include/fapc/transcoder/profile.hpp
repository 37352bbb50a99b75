// Parameter profiles (docs/profiles.md): free animation parameter names (Mimic's `jaw`,
// `eyelid_right`, ...) mapped onto FAPs with a scale. Standard FAP names need no profile.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc {

struct FapContribution {
  int fap = 0;       // 3..68
  double scale = 1;  // FAP value = parameter value * scale
  friend bool operator==(const FapContribution&, const FapContribution&) = default;
};

struct Profile {
  std::string name;  // file name or "default"
  // A name may drive several FAPs (lookat_x turns both eyeballs).
  std::map<std::string, std::vector<FapContribution>, std::less<>> parameters;
};

// The bundled profile: covers every free name of the Mimic paper's examples. Its text, in the
// profile format, is a starting point for custom profiles (docs/profiles.md shows it).
const Profile& default_profile();
std::string_view default_profile_text();

// The profile text format: `name fap scale` per line (fap by name or number), `#` comments; a name
// on several lines drives several FAPs. Errors at file:line:col.
Result<Profile> parse_profile(std::string_view text, const std::string& file_name);
Result<Profile> load_profile(const std::string& path);

// "viseme.PP" -> {1, 1}, "expression.Joy" -> {2, 1}: the FAP (1 or 2) and the viseme or
// expression number (names of fap_table.hpp, any case). Empty for every other target.
struct WeightTarget {
  int fap = 0;
  int number = 0;
};
std::optional<WeightTarget> weight_target(std::string_view target);

// What a clip target drives: a standard FAP name or number gives {fap, 1}; a profile name its
// contributions; "viseme.X"/"expression.X" give FAP 1 / FAP 2 (scale 1). Empty when unknown.
std::vector<FapContribution> resolve_target(std::string_view target, const Profile& profile);

// "unknown parameter 'jw'; did you mean jaw, open_jaw, ...?" over FAP names and profile names.
std::string unknown_parameter_message(std::string_view name, const Profile& profile);

}  // namespace fapc

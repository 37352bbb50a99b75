#include "track_read.hpp"

namespace fapc::pipeline::bridges {

Diagnostic columns_not_read(const std::string& file, WarningCode code, const std::vector<std::string>& names,
                            std::string_view why) {
  constexpr std::size_t kShown = 6;
  std::string list;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i) list += (i ? ", " : "") + names[i];
  if (names.size() > kShown) list += " and " + std::to_string(names.size() - kShown) + " more";
  return make_warning(code, Location::text(file, 1, 1),
                      std::to_string(names.size()) + " column" + (names.size() == 1 ? " is" : "s are") + " not read (" +
                          std::string(why) + "): " + list);
}

}  // namespace fapc::pipeline::bridges

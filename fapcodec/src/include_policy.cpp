#include "fapc/codec/include_policy.hpp"

#include <filesystem>

#include "fapc/codec/codes.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

// Whether `path` is `folder` or lies under it, component by component (so "/a/bc" is not under
// "/a/b"); both are absolute and normal. Empty components come from trailing slashes.
bool lies_inside(const fs::path& path, const fs::path& folder) {
  auto p = path.begin();
  for (const fs::path& part : folder) {
    if (part.empty()) continue;
    while (p != path.end() && p->empty()) ++p;
    if (p == path.end() || *p != part) return false;
    ++p;
  }
  return true;
}

// The absolute form with symbolic links and ".." resolved as far as the path exists.
fs::path resolved(const fs::path& path, std::error_code& error) {
  return fs::weakly_canonical(fs::absolute(path.empty() ? fs::path(".") : path, error), error);
}

std::string shown(const std::string& folder) { return folder.empty() ? "." : folder; }

}  // namespace

Result<std::string> resolve_include(std::string_view name, const std::string& including_file,
                                    const IncludePolicy& policy, const Location& where) {
  const fs::path written{std::string(name)};
  const fs::path base =
      policy.base_folder.empty() ? fs::path(including_file).parent_path() : fs::path(policy.base_folder);
  const fs::path joined = (written.is_absolute() ? written : base / written).lexically_normal();
  std::error_code error;
  const fs::path target = resolved(joined, error);
  if (error) {
    return make_error(codes::include::unresolvable, where,
                      "cannot resolve '" + std::string(name) + "': " + error.message());
  }
  std::vector<std::string> allowed = policy.allowed_folders;
  if (allowed.empty()) allowed.push_back(base.string());
  for (const std::string& folder : allowed) {
    const fs::path root = resolved(folder, error);
    if (!error && lies_inside(target, root)) return joined.string();
    error.clear();
  }
  std::string folders;
  for (const std::string& folder : allowed) folders += (folders.empty() ? "'" : ", '") + shown(folder) + "'";
  const char* how = written.is_absolute() ? "is an absolute path outside" : "leads outside";
  return make_error(codes::include::outside_allowed, where,
                    "'" + std::string(name) + "' " + how + " the folders a script may include from (" + folders +
                        "); --allow-include DIR allows another (docs/security.md)");
}

}  // namespace fapc

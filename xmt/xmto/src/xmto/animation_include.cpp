#include "xmto/animation_include.hpp"

#include <filesystem>

#include "fapc/codec/include_policy.hpp"
#include "fapc/xml/text.hpp"
#include "fapc/xmto/codes.hpp"

namespace fapc::xmto {
namespace {

namespace fs = std::filesystem;

// Two names for one file compare equal when both exist; otherwise by their normal form.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::equivalent(a, b, error)) return true;
  return fs::path(a).lexically_normal() == fs::path(b).lexically_normal();
}

std::string chain_text(const std::vector<std::string>& chain, const std::string& last) {
  std::string out;
  for (const std::string& link : chain) out += link + " -> ";
  return out + last;
}

}  // namespace

Result<Included> load_included(const xml::XmlDocument& doc, const xmlNode* element, const XmtoOptions& options,
                               Diagnostics& warnings) {
  const auto src = xml::attribute(element, "src");
  const auto ref = xml::attribute(element, "ref");
  const char* used = src ? "src" : "ref";
  if (!src && !ref)
    return doc.error(codes::xmto::missing_attribute, element, "animation needs src (or ref) naming the input to place");
  if (src && ref) warnings.push_back(doc.warning(element, "ref", "ref is ignored: src is given"));
  std::string_view name = xml::trim(src ? *src : *ref);
  if (name.starts_with("file:")) name.remove_prefix(5);
  if (name.empty()) return doc.error(codes::xmto::bad_source, element, used, std::string(used) + " is empty");
  if (name.find("://") != std::string_view::npos) {
    return doc.error(codes::xmto::bad_source, element, used,
                     std::string(used) + " '" + std::string(name) + "': only local files can be placed, not URLs");
  }
  Result<std::string> path = resolve_include(name, doc.file(), options.includes, doc.where(element, used));
  if (!path) {
    Diagnostic refused = path.error();
    refused.source_line = doc.line_text(refused.where.line);
    return refused;
  }
  Included included;
  included.path = *path;

  std::vector<std::string> chain = options.including;
  chain.push_back(doc.file());
  for (const std::string& open : chain) {
    if (same_file(open, included.path)) {
      return doc.error(codes::xmto::include_cycle, element, used,
                       "animation includes a document that is being read: " + chain_text(chain, included.path));
    }
  }
  if (chain.size() > kMaxIncludeDepth) {
    return doc.error(codes::limit::nesting_depth, element, used,
                     "animations nested more than " + std::to_string(kMaxIncludeDepth) +
                         " documents deep: " + chain_text(chain, included.path));
  }
  if (!options.load_animation) {
    return doc.error(codes::xmto::no_loader, element,
                     "animation elements need a loader for other inputs (none was given)");
  }
  auto loaded = options.load_animation(included.path, doc.where(element, used));
  if (!loaded) return loaded.error();
  included.animation = std::move(*loaded);
  return included;
}

}  // namespace fapc::xmto

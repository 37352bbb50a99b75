// The FML reader (docs/fml.md): an Arya-DiPaola Face Modeling Language document
// lowered to the shared timeline through fapc::schedule(). Moves ramp their target from its
// current value to theirs and hold it; talk becomes FAP 1 visemes, expr FAP 2 expressions, hdmv
// the head rotation FAPs; excl branches are chosen by event values given up front.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/transcoder/profile.hpp"
#include "fapc/transcoder/timeline.hpp"

namespace fapc::xmt {

struct FmlOptions {
  // Event values (--event NAME=VALUE); they win over the model's <event val>.
  std::map<std::string, std::string> events;
  // The story's end when the document gives none (--duration): lets indefinite repeats end.
  std::optional<double> duration;
  // Names that `param` moves may use besides the FAP names; nullptr: the default profile.
  const Profile* profile = nullptr;
  double visemes_per_second = 12;  // talk text: the speaking rate of the letter approximation
  // Reads the phoneme file of `talk file=` (a path already resolved against the document's
  // folder); empty: read from disk.
  std::function<Result<std::string>(const std::string& path)> read_file;
  // Which files `talk file=` may name (docs/security.md); by default the document's folder tree.
  IncludePolicy includes;
};

struct FmlDocument {
  Timeline timeline;  // explicit_end: the story's end
  std::string character;                                   // model <character name>
  std::vector<std::pair<std::string, std::string>> events;  // name, the value used ("" when none)
  std::vector<std::string> templates;                      // model template names
  std::vector<std::string> phoneme_files;                  // resolved paths of talk file=
  Diagnostics warnings;
};

// Errors (file:line:col): not well-formed XML, another format than FML (named: Greta FML-APML,
// APML, BML, Xface SMIL-Agent, XMT), malformed timing or values, unknown templates, recursion.
Result<FmlDocument> read_fml(std::string_view text, const std::string& file_name, const FmlOptions& options = {});
Result<FmlDocument> load_fml(const std::string& path, const FmlOptions& options = {});

}  // namespace fapc::xmt

// The FML reader (docs/fml.md): an Arya-DiPaola Face Modeling Language document
// lowered to the shared timeline through fapc::timeline::schedule(). Moves ramp their target from its
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
#include "fapc/codec/limits.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/profile.hpp"
#include "fapc/transcoder/reader_options.hpp"
#include "fapc/transcoder/speech.hpp"

namespace fapc::fml {

struct FmlDocument {
  Timeline timeline;                                        // explicit_end: the story's end
  std::string character;                                    // model <character name>
  std::vector<std::pair<std::string, std::string>> events;  // name, the value used ("" when none)
  std::vector<std::string> templates;                       // model template names
  std::vector<std::string> phoneme_files;                   // resolved paths of talk file=
  std::vector<std::string> languages;                       // the languages talk text was spoken in
  Diagnostics warnings;
};

// Errors (file:line:col): not well-formed XML, another format than FML (named: Greta FML-APML,
// APML, BML, Xface SMIL-Agent, XMT), malformed timing or values, unknown templates, recursion.
Result<FmlDocument> read_fml(std::string_view text, const std::string& file_name, const ReaderOptions& options = {});
Result<FmlDocument> load_fml(const std::string& path, const ReaderOptions& options = {});

}  // namespace fapc::fml

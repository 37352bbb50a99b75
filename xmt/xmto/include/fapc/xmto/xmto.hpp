// The XMT-Omega reader (docs/xmt-omega.md): an XMT-O document lowered to the
// shared timeline through fapc::timeline::schedule(). Reads the SMIL timing and animation subset that
// describes face animation; `animation src` places another input, loaded by a caller-given
// function, so this library depends on no other front end.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/fml/fml.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/reader_options.hpp"
#include "fapc/xml/clock_value.hpp"  // parse_clock_value, part of this reader's interface

namespace fapc::xmto {

// What an `animation src` element brings: the included input's timeline (starting at 0; its end()
// is the element's intrinsic duration) and the warnings its reader gave.
struct IncludedAnimation {
  Timeline timeline;
  Diagnostics warnings;
};

// `resolved_path` is the src/ref resolved against the including document's folder; `where` is the
// animation element, for errors the loader wants to place there.
using AnimationLoader =
    std::function<Result<IncludedAnimation>(const std::string& resolved_path, const Location& where)>;

// The reader options every reader takes (limits.max_runs: the clips after repeats in the whole
// document; limits.max_decompressed_bytes: the largest file an `audio` element may read, its WAV
// and the .pho beside it; includes: which files `animation src` and `audio` may name; frames fps
// 0 for an included document, whose frames are never made; the speech, events and profile of the
// FML moves written in the document: docs/xmt-omega.md, "FML moves inside XMT-Omega"), and what
// only XMT-Omega has beside them:
struct XmtoOptions : ReaderOptions {
  XmtoOptions() = default;
  explicit XmtoOptions(ReaderOptions common) : ReaderOptions(std::move(common)) {}
  // Without a loader an `animation` element is an error (nothing can read what it names).
  AnimationLoader load_animation;
  // Documents being read around this one, outermost first (their paths as given): an `animation`
  // that names one of them, or this document, is an inclusion cycle and an error.
  std::vector<std::string> including;
};

struct XmtoDocument {
  Timeline timeline;                                      // explicit_end: the body's end
  std::vector<std::pair<std::string, std::string>> meta;  // head/meta name and content
  std::vector<std::string> included;  // resolved paths of `animation` inputs, `audio` WAV and .pho files
  Diagnostics warnings;
};

// Errors (file:line:col): not well-formed XML, a root other than XMT-O (XMT-A says it is not an
// input), malformed timing or values, an unknown attributeName, a failed include.
Result<XmtoDocument> read_xmto(std::string_view text, const std::string& file_name, const XmtoOptions& options = {});
Result<XmtoDocument> load_xmto(const std::string& path, const XmtoOptions& options = {});

// The XMT-Omega namespace (presumed by analogy with XMT-A; documents are recognised by the root
// name, with or without it).
inline constexpr std::string_view kXmtoNamespace = "urn:mpeg:mpeg4:xmto:schema:2002";

}  // namespace fapc::xmto

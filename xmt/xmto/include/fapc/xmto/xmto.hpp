// The XMT-Omega reader (docs/xmt-omega.md): an XMT-O document lowered to the
// shared timeline through fapc::schedule(). Reads the SMIL timing and animation subset that
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
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/timeline.hpp"
#include "fapc/xml/clock_value.hpp"  // parse_clock_value, part of this reader's interface

namespace fapc::xmt {

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

struct XmtoOptions {
  // Without a loader an `animation` element is an error (nothing can read what it names).
  AnimationLoader load_animation;
  // The end of the body when the document gives none (--duration): lets indefinite repeats and
  // open-ended elements at the top level end.
  std::optional<double> duration;
  // The most runs (clips after repeats) in the whole document: Limits::max_runs.
  std::int64_t max_runs = Limits{}.max_runs;
  // The frames the body will be rendered at: a body too long for them is refused once it is
  // scheduled, before its clips are made (the error FrameStream::start would give). fps 0:
  // unchecked (an included document, whose frames are never made).
  FrameBudget frames;
  // Documents being read around this one, outermost first (their paths as given): an `animation`
  // that names one of them, or this document, is an inclusion cycle and an error.
  std::vector<std::string> including;
  // Which files `animation src` may name (docs/security.md); by default the document's folder
  // tree. (The FML moves' talk files follow fml.includes.)
  IncludePolicy includes;
  // The largest file an `audio` element may read (its WAV, the .pho beside it), checked before
  // reading: Limits::max_decompressed_bytes, --max-decompressed-bytes.
  std::int64_t max_audio_bytes = Limits{}.max_decompressed_bytes;
  // FML moves written in the document (docs/xmt-omega.md, "FML moves inside XMT-Omega"): event
  // values for repeat, the profile for param, the speech engine and voice for talk.
  FmlOptions fml;
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

}  // namespace fapc::xmt

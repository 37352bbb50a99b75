// A BML sync reference as written in a behaviour's timing attribute or a constraint's `ref`:
// a plain time in seconds ("2.5"), or `[block:]behaviour:syncpoint[+|-offset]`
// ("speech1:sync4", "bml2:nod1:stroke-0.5"). Parsing only; what the names mean is the solver's.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace fapc::bml {

struct SyncRef {
  bool absolute = false;  // a plain time: `offset` seconds from the block's start
  std::string block;      // empty: this block
  std::string behaviour;
  std::string sync;
  double offset = 0;
};

// nullopt with `why` set when the text is not a sync reference.
std::optional<SyncRef> parse_sync_ref(std::string_view text, std::string& why);

// A finite decimal number of seconds ("2", "-0.5", "1e-3"), nothing else around it but blanks.
std::optional<double> parse_seconds(std::string_view text);

// Seconds as messages show them ("2.5 s", three significant digits).
std::string seconds_text(double seconds);

}  // namespace fapc::bml

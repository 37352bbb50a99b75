// An option given for an input whose kind does not read it (`--lexicon` to a .fap) changes
// nothing; the user is told so rather than left to believe it did (docs/cli.md, "Options a kind
// does not read"). The rows say which kinds read which options: an option is a reading option when
// some input row names it.
#include <algorithm>

#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline {

namespace {

bool names(const std::vector<std::string>& options, const std::string& option) {
  return std::find(options.begin(), options.end(), option) != options.end();
}

}  // namespace

Diagnostics options_not_read(const std::string& input, const std::vector<const OutputFormat*>& writers,
                             const ConvertOptions& options) {
  Diagnostics warnings;
  const InputFormat* reader = reader_for(input, options);
  if (!reader) return warnings;  // the unknown kind is the load's error
  for (const std::string& option : options.given) {
    if (names(reader->options, option)) continue;
    if (std::any_of(writers.begin(), writers.end(), [&](const OutputFormat* w) { return names(w->options, option); }))
      continue;
    const auto readers = inputs_where([&option](const InputFormat& f) { return names(f.options, option); });
    if (readers.empty()) continue;  // not a reading option: the command's own, or an output's
    warnings.push_back(make_warning(codes::format::option_not_read, Location::whole_file(input),
                                    "--" + option + " changes nothing here: " + reader->kind +
                                        " inputs do not read it (" + kind_list(readers) + " do)"));
  }
  return warnings;
}

}  // namespace fapc::pipeline

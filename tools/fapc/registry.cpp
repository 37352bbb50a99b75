#include "fapc/registry.hpp"

namespace fapc::cli {

namespace {

// Function-local statics: the registering objects of other files may run before this file's
// globals are initialised.
std::map<std::string, Command>& command_table() {
  static std::map<std::string, Command> table;
  return table;
}
std::vector<InputFormat>& input_table() {
  static std::vector<InputFormat> table;
  return table;
}
std::vector<OutputFormat>& output_table() {
  static std::vector<OutputFormat> table;
  return table;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

template <class Format>
const Format* by_extension(const std::vector<Format>& table, const std::string& path) {
  const Format* best = nullptr;
  std::size_t best_length = 0;
  for (const Format& f : table)
    for (const std::string& ext : f.extensions)
      if (ext.size() > best_length && ends_with(path, ext)) {
        best = &f;
        best_length = ext.size();
      }
  return best;
}

template <class Format>
const Format* by_kind(const std::vector<Format>& table, const std::string& kind) {
  for (const Format& f : table)
    if (f.kind == kind) return &f;
  return nullptr;
}

}  // namespace

RegisterCommand::RegisterCommand(std::string name, std::string usage, CommandFn run) {
  command_table()[name] = Command{name, std::move(usage), run};
}
const std::map<std::string, Command>& commands() { return command_table(); }

RegisterInput::RegisterInput(InputFormat format) { input_table().push_back(std::move(format)); }
RegisterOutput::RegisterOutput(OutputFormat format) { output_table().push_back(std::move(format)); }

const InputFormat* input_format_for(const std::string& path) {
  return by_extension(input_table(), path);
}
const OutputFormat* output_format_for(const std::string& path) {
  return by_extension(output_table(), path);
}
const InputFormat* input_format_named(const std::string& kind) {
  return by_kind(input_table(), kind);
}
const OutputFormat* output_format_named(const std::string& kind) {
  return by_kind(output_table(), kind);
}

Result<Loaded> load_input(const std::string& path, const ConvertOptions& options) {
  const InputFormat* format = input_format_for(path);
  if (!format)
    return make_error(Location{path, 0, 0, -1},
                      "unknown input kind (expected .fap, .fap.gz, .fba, .mp4, .mimic, .fml or .xmt)");
  Result<Loaded> loaded = format->load(path, options);
  if (loaded) loaded->origin = path;
  return loaded;
}

}  // namespace fapc::cli

#include "fapc/registry.hpp"

#include <filesystem>

#include "fapc/codec/deep_stack.hpp"

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

// An input being read: its path as given, and as resolved, to recognise it under another name.
struct Reading {
  std::string path;
  std::filesystem::path resolved;
};

// Per thread: batch reads inputs on several threads; an included input is read on a thread of its
// own, which starts with a copy of its includer's chain.
thread_local std::vector<Reading> reading_chain;

std::filesystem::path resolved_path(const std::string& path) {
  std::error_code error;
  std::filesystem::path out = std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
  return error ? std::filesystem::path(path).lexically_normal() : out;
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
  const ReadingInput reading(path, options);
  return format->load(path, reading.options());
}

ReadingInput::ReadingInput(const std::string& path, const ConvertOptions& options) : options_(options) {
  IncludePolicy& includes = options_.includes;
  if (reading_chain.empty()) {
    const std::string own = includes.base_folder.empty()
                                ? std::filesystem::path(path).parent_path().string()
                                : includes.base_folder;
    includes.allowed_folders.insert(includes.allowed_folders.begin(), own);
  } else {
    includes.base_folder.clear();  // the working folder was standard input's, not its includes'
  }
  reading_chain.push_back(Reading{path, resolved_path(path)});
}

ReadingInput::~ReadingInput() { reading_chain.pop_back(); }

std::vector<std::string> inputs_being_read() {
  std::vector<std::string> out;
  for (const Reading& r : reading_chain) out.push_back(r.path);
  return out;
}

Result<Loaded> load_included_input(const std::string& path, const Location& where,
                                   const ConvertOptions& options) {
  const std::filesystem::path resolved = resolved_path(path);
  std::string chain;
  for (const Reading& r : reading_chain) chain += r.path + " -> ";
  chain += path;
  for (const Reading& r : reading_chain) {
    if (r.resolved == resolved) return make_error(where, "include cycle: " + chain);
  }
  if (reading_chain.size() >= kMaxIncludeDepth) {
    return make_error(ErrorKind::limit_exceeded, where,
                      "inputs included more than " + std::to_string(kMaxIncludeDepth) +
                          " levels deep (the include depth limit): " + chain);
  }
  const std::vector<Reading> includers = reading_chain;
  std::optional<Result<Loaded>> loaded;
  run_on_deep_stack([&] {
    reading_chain = includers;
    loaded.emplace(load_input(path, options));
  });
  return std::move(*loaded);
}

}  // namespace fapc::cli

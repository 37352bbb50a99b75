#include "input_chain.hpp"

#include <filesystem>

#include "fapc/codec/deep_stack.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline {

namespace {

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

}  // namespace

ReadingInput::ReadingInput(const std::string& path, const ConvertOptions& options) : options_(options) {
  options_.input_kind.clear();  // --from names the top input's kind, not its includes'
  IncludePolicy& includes = options_.includes;
  if (reading_chain.empty()) {
    const std::string own =
        includes.base_folder.empty() ? std::filesystem::path(path).parent_path().string() : includes.base_folder;
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

Result<Loaded> load_included_input(const std::string& path, const Location& where, const ConvertOptions& options) {
  const std::filesystem::path resolved = resolved_path(path);
  std::string chain;
  for (const Reading& r : reading_chain) chain += r.path + " -> ";
  chain += path;
  for (const Reading& r : reading_chain) {
    if (r.resolved == resolved) return make_error(codes::input::include_cycle, where, "include cycle: " + chain);
  }
  if (reading_chain.size() >= kMaxIncludeDepth) {
    return make_error(codes::limit::nesting_depth, where,
                      "inputs included more than " + std::to_string(kMaxIncludeDepth) +
                          " levels deep (the include depth limit): " + chain);
  }
  const std::vector<Reading> includers = reading_chain;
  std::optional<Result<Loaded>> loaded;
  run_on_deep_stack([&] {
    reading_chain = includers;
    loaded.emplace(load(path, options));
  });
  return std::move(*loaded);
}

}  // namespace fapc::pipeline

// Compiling small Mimic programs in tests, with .xpr files given inline.
#pragma once

#include <map>
#include <string>

#include <gtest/gtest.h>

#include "fapc/codec/codes.hpp"
#include "fapc/transcoder/mimic.hpp"
#include "fapc/transcoder/render.hpp"
#include "support/test_support.hpp"

namespace fapc::test {

inline Result<MimicProgram> compile(const std::string& source, const std::map<std::string, std::string>& files = {}) {
  ReaderOptions options;
  options.read_file = [files](const std::string& path) -> Result<std::string> {
    const auto found = files.find(path);
    if (found == files.end()) return make_error(codes::io::cannot_open, Location::whole_file(path), "no such file");
    return found->second;
  };
  return compile_mimic(source, "t.mimic", options);
}

// The timeline of a program that must compile.
inline Timeline timeline_of(const std::string& source, const std::map<std::string, std::string>& files = {}) {
  Result<MimicProgram> program = compile(source, files);
  EXPECT_TRUE(program.ok()) << (program.ok() ? "" : format_diagnostic(program.error()));
  return program.ok() ? program->timeline : Timeline{};
}

// The diagnostic of a program that must fail, with its caret lines.
inline std::string error_of(const std::string& source, const std::map<std::string, std::string>& files = {}) {
  Result<MimicProgram> program = compile(source, files);
  EXPECT_FALSE(program.ok()) << "compiled: " << source;
  return program.ok() ? std::string() : render_with_caret(program.error());
}

}  // namespace fapc::test

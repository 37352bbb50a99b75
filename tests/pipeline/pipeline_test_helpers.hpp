// A fresh folder per test, removed afterwards; the usual way of converting, to check others by.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/convert.hpp"
#include "support/test_support.hpp"

namespace fapc::test {

class TempFolder {
 public:
  TempFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("fapc-pipeline-" + std::string(info->test_suite_name()) + "-" + info->name() + "-" +
             std::to_string(::getpid()));  // two builds' suites may run at once
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The usual way of converting, against which the streamed ways are checked: load, then each
// writer's bytes, up to the first error (with --strict, warnings refuse the outputs as convert does).
struct LoadedWay {
  std::vector<std::string> bytes;
  Diagnostics warnings;
  std::size_t frames = 0;
  std::optional<Diagnostic> error;
};

inline LoadedWay load_then_write(const std::string& input, const std::vector<pipeline::OutputRequest>& outputs,
                                 const pipeline::ConvertOptions& options) {
  LoadedWay out;
  auto loaded = pipeline::load(input, options);
  if (!loaded) {
    out.error = loaded.error();
    return out;
  }
  out.warnings = loaded->warnings;
  out.frames = loaded->frames.frames.size();
  if (options.strict && !loaded->warnings.empty()) {
    out.error = make_error(
        codes::output::strict_warnings, Location::whole_file(input),
        std::to_string(loaded->warnings.size()) + " warning(s) treated as errors (--strict); nothing written");
    return out;
  }
  for (const auto& request : outputs) {
    auto bytes = pipeline::render_output(*loaded, request, options);
    if (!bytes) {
      out.error = bytes.error();
      return out;
    }
    out.bytes.push_back(*bytes);
  }
  return out;
}

// The sweeps that compare two ways of converting on every corpus file take every third file in
// the sanitizer build (FAPC_SANITIZED_BUILD, set by tests/CMakeLists.txt), which runs 10-20 times
// slower: both ways run the same code on each file, so the sample exercises it under the
// sanitizers and the plain build compares every file. Counts a sweep expects scale with it.
#ifdef FAPC_SANITIZED_BUILD
inline constexpr std::size_t kSweepStride = 3;
#else
inline constexpr std::size_t kSweepStride = 1;
#endif
inline std::vector<std::string> sweep_sample(std::vector<std::string> files) {
  std::sort(files.begin(), files.end());
  std::vector<std::string> sample;
  for (std::size_t k = 0; k < files.size(); k += kSweepStride) sample.push_back(std::move(files[k]));
  return sample;
}

// Every script of the corpus, good and bad (Mimic, FML, XMT-Omega), for tests that compare two
// ways of compiling them (a sample under the sanitizers).
inline std::vector<std::string> corpus_scripts() {
  std::vector<std::string> scripts;
  for (const char* folder : {"examples", "mimic", "fml", "xmto", "mimic-bad", "fml-bad", "xmto-bad"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(corpus_dir() + "/" + folder)) {
      const std::string ext = entry.path().extension().string();
      if (entry.is_regular_file() && (ext == ".mimic" || ext == ".mim" || ext == ".fml" || ext == ".xmt"))
        scripts.push_back(entry.path().string());
    }
  }
  return sweep_sample(std::move(scripts));
}

// A conversion's result against the usual way's: the same error (message and kind), the same
// warnings, and each output written with the usual bytes or, after the error, not at all.
inline void expect_as_loaded(const pipeline::ConvertResult& result, const LoadedWay& expected,
                             const std::vector<pipeline::OutputRequest>& outputs) {
  if (expected.error) {
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(format_diagnostic(*result.error), format_diagnostic(*expected.error));
    EXPECT_EQ(result.error->kind, expected.error->kind);
  } else {
    ASSERT_TRUE(result.ok()) << format_diagnostic(*result.error);
  }
  ASSERT_EQ(result.warnings.size(), expected.warnings.size());
  for (std::size_t w = 0; w < expected.warnings.size(); ++w)
    EXPECT_EQ(format_diagnostic(result.warnings[w]), format_diagnostic(expected.warnings[w]));
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (i < expected.bytes.size())
      EXPECT_EQ(read_text(outputs[i].path), expected.bytes[i]) << outputs[i].path;
    else
      EXPECT_FALSE(std::filesystem::exists(outputs[i].path)) << outputs[i].path;
  }
}

}  // namespace fapc::test

// The .fap files a corpus sweep goes over: every one under corpus/ outside the folders of bad
// inputs, or every eighth of them in the sanitizer build (FAPC_SANITIZED_BUILD, set by
// tests/CMakeLists.txt for the suites that sweep), which runs 10 to 30 times slower
// (docs/testing.md). Header-only, so each suite's own definition decides.
#pragma once

#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace fapc::test {

#ifdef FAPC_SANITIZED_BUILD
inline constexpr std::size_t kSweepEveryNthFile = 8;
#else
inline constexpr std::size_t kSweepEveryNthFile = 1;
#endif

// Every readable corpus .fap, however many the build sweeps.
inline std::vector<std::string> all_good_corpus_fap_files() {
  std::vector<std::string> files;
  for (const std::string& path : files_under(corpus_dir(), ".fap"))
    if (path.find("-bad/") == std::string::npos) files.push_back(path);
  return files;
}

// The files this build sweeps.
inline std::vector<std::string> sweep_fap_files() {
  const auto all = all_good_corpus_fap_files();
  std::vector<std::string> files;
  for (std::size_t f = 0; f < all.size(); f += kSweepEveryNthFile) files.push_back(all[f]);
  return files;
}

}  // namespace fapc::test

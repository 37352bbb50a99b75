// docs/architecture.md's matrix of formats against what they carry and what the engine may do with
// them is the reader/writer table itself: this test makes the matrix from the rows and compares
// it with the one between the markers (FAPC_REGENERATE_GOLDEN=1 rewrites it, docs/testing.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "fapc/pipeline/registry.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

constexpr const char* kBegin = "<!-- format matrix: begin -->\n";
constexpr const char* kEnd = "<!-- format matrix: end -->\n";

std::string mark(bool yes) { return yes ? "yes" : ""; }

template <class Format>
std::string extensions_of(const Format& f) {
  std::string out;
  for (const std::string& ext : f.extensions) out += (out.empty() ? "`" : ", `") + ext + "`";
  return out;
}

std::string matrix() {
  std::ostringstream out;
  out << "| reader | extensions | a script (timeline) | streams its frames | an FBA stream (verify, decode) |\n"
      << "|---|---|---|---|---|\n";
  for (const pipeline::InputFormat& f : pipeline::formats().inputs())
    out << "| `" << f.kind << "` | " << extensions_of(f) << " | " << mark(f.timeline) << " | "
        << mark(bool(f.frames) || f.timeline) << " | " << mark(bool(f.verify_stream)) << " |\n";
  out << "\n| writer | extensions | takes frames one at a time | reads the frames | reads the curves | reads the "
         "voice | draws the face |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const pipeline::OutputFormat& f : pipeline::formats().outputs())
    out << "| `" << f.kind << "` | " << extensions_of(f) << " | " << mark(bool(f.frame_writer)) << " | "
        << mark(f.uses_frames) << " | " << mark(f.uses_curves) << " | " << mark(f.uses_audio) << " | "
        << mark(f.picture) << " |\n";
  return out.str();
}

TEST(FormatMatrix, TheArchitectureTourShowsTheTable) {
  test::expect_generated_region("docs/architecture.md", kBegin, kEnd, matrix(), "the reader/writer table");
}

}  // namespace
}  // namespace fapc

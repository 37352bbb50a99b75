// Every document of corpus/xmto/ read through the library, with a loader for the inputs the
// library can reach on its own (.fap, .fba and nested XMT-Omega): its timeline dump must match the
// golden corpus/golden/xmto/<name>.timeline. The command tests write the same golden through the
// fapc program (tests/command/xmto_golden_test.cpp), so the two paths are held to one result.
// Documents that place a Mimic program or an FML document are left to the program.
#include <gtest/gtest.h>

#include <filesystem>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/speech/engine.hpp"
#include "fapc/timeline/timeline_from_frames.hpp"
#include "fapc/xmto/xmto.hpp"
#include "support/test_support.hpp"

namespace fapc::xmto {
namespace {

namespace fs = std::filesystem;

// Paths are relative to the source folder, as when fapc runs there.
Result<IncludedAnimation> load(const std::string& path, std::vector<std::string> including) {
  const std::string text = test::read_text(test::source_dir() + "/" + path);
  if (path.ends_with(".xmt")) {
    auto nested = read_xmto(text, path, [&] {
      XmtoOptions options;
      options.including = including;
      // Spoken as `fapc` speaks it: the goldens are shared with the command tests.
      options.speech.synthesize = speech::engine();
      options.load_animation = [&](const std::string& inner, const Location&) {
        std::vector<std::string> chain = including;
        chain.push_back(path);
        return load(inner, chain);
      };
      return options;
    }());
    if (!nested) return nested.error();
    return IncludedAnimation{std::move(nested->timeline), std::move(nested->warnings)};
  }
  if (path.ends_with(".fba")) {
    FbaDecodeOptions options;
    options.file = path;
    auto decoded = decode_fba(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), options);
    if (!decoded) return decoded.error();
    return IncludedAnimation{timeline_from_frames(decoded->sequence, 0, Location::whole_file(path)),
                             std::move(decoded->warnings)};
  }
  auto frames = read_fap_text(text, path);
  if (!frames) return frames.error();
  return IncludedAnimation{timeline_from_frames(frames->sequence, 0, Location::whole_file(path)),
                           std::move(frames->warnings)};
}

// Mimic and FML inputs need their front ends; an audio element reads its WAV relative to the
// working folder, which is not the source folder under ctest (xmto_audio_test.cpp reads it, and
// tests/command/xmto_golden_test.cpp checks its .timeline golden through fapc).
bool needs_other_front_ends(const std::string& text) {
  return text.find(".mimic\"") != std::string::npos || text.find(".fml\"") != std::string::npos ||
         text.find("<audio ") != std::string::npos;
}

TEST(XmtoCorpus, TimelinesMatchTheirGoldens) {
  const std::vector<std::string> files = test::files_under(test::corpus_dir() + "/xmto", ".xmt");
  ASSERT_GE(files.size(), 5u);
  int read = 0;
  for (const std::string& full : files) {
    const std::string path = fs::relative(full, test::source_dir()).string();
    const std::string text = test::read_text(full);
    if (needs_other_front_ends(text)) continue;
    const auto included = load(path, {});
    ASSERT_TRUE(included.ok()) << format_diagnostic(included.error());
    const std::string stem = fs::path(path).stem().string();
    test::expect_golden("golden/xmto/" + stem + ".timeline", dump(included->timeline));
    ++read;
  }
  EXPECT_GE(read, 5);
}

// The corpus uses every element and attribute the reader supports.
TEST(XmtoCorpus, UsesEverySupportedElementAndAttribute) {
  std::string all;
  for (const std::string& path : test::files_under(test::corpus_dir() + "/xmto", ".xmt")) all += test::read_text(path);
  for (const char* needle : {"<head>",
                             "<meta ",
                             "<body>",
                             "<par",
                             "<seq",
                             "<excl",
                             "<animate ",
                             "<set ",
                             "<animation ",
                             " begin=",
                             " dur=",
                             " end=",
                             " repeatCount=",
                             " repeatDur=",
                             " fill=",
                             " attributeName=",
                             "<audio ",
                             " from=",
                             " to=",
                             " by=",
                             " values=",
                             " keyTimes=",
                             "calcMode=\"linear\"",
                             "calcMode=\"discrete\"",
                             "calcMode=\"paced\"",
                             "additive=\"sum\"",
                             "additive=\"replace\"",
                             "accumulate=\"sum\"",
                             " src=",
                             " ref=",
                             "viseme.",
                             "expression.",
                             "repeatCount=\"indefinite\""}) {
    EXPECT_NE(all.find(needle), std::string::npos) << needle;
  }
}

}  // namespace
}  // namespace fapc::xmto

// An affect or action anchored to a speech mark starts with the marked word, measured on the
// audio as the BML and FML speech sync tests measure it: the word after a sentence pause is heard
// as a new voiced stretch (support/voiced_segments.hpp), whose onset must be within one frame of
// the first rendered frame where the anchored behaviour moves the face.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/sync_to_word.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

std::string write_smil(const std::string& body) {
  const fs::path dir = test::scratch_folder("smil-sync");
  const fs::path path = dir / "sync.smil";
  std::ofstream(path) << body;
  return path.string();
}

void expect_synced(const std::string& body, int fap, std::size_t stretch) {
  test::expect_moves_with_word(write_smil(body), fap, stretch);
}

TEST(SmilSpeechSync, AnAffectAnchoredToAMarkStartsWithTheMarkedWord) {
  // FAP 31, raise_l_i_eyebrow: Surprise raises the brows.
  expect_synced(R"(<par system-language="english">
  <speech channel="alice-voice" id="s1">Good morning to you. <mark id="*1*"/>Look at this.</speech>
  <speech-animation affect="Surprise" content-id="s1" content-begin="*1*"/>
</par>)",
                31, 1);
}

TEST(SmilSpeechSync, AnActionAnchoredToAMarkInALaterSpeechStartsWithItsWord) {
  // FAP 23, yaw_l_eyeball: LookLeft turns the eyes; the speech starts after another in a seq.
  expect_synced(R"(<par system-language="english">
  <seq>
    <speech channel="alice-voice" id="s0">Hello.</speech>
    <speech channel="alice-voice" id="s1" begin="0.5s">I am here. <mark id="m"/>Really here.</speech>
  </seq>
  <action channel="alice-eyes" action-type="turning" content-id="s1" content-begin="m"><parameter>LookLeft</parameter></action>
</par>)",
                23, 2);
}

}  // namespace
}  // namespace fapc

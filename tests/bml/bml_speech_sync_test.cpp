// A behaviour synced to a speech mark starts with the marked word, measured on the audio as
// tests/speech/speech_sync_test.cpp measures the mouth: the word after a sentence pause is heard
// as a new voiced stretch, whose onset (found by energy) must be within one frame of the first
// rendered frame where the synced behaviour moves the face.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "support/sync_to_word.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

std::string write_bml(const std::string& name, const std::string& body) {
  const fs::path dir = test::scratch_folder("bml-sync");
  const fs::path path = dir / name;
  std::ofstream(path) << "<bml xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\" id=\"b1\">" << body << "</bml>\n";
  return path.string();
}

void expect_synced(const std::string& body, int fap, std::size_t stretch) {
  test::expect_moves_with_word(write_bml("sync.bml", body), fap, stretch);
}

TEST(BmlSpeechSync, ANodSyncedToAMarkStartsWithTheMarkedWord) {
  expect_synced(R"(<speech id="s1"><text>Good morning to you. <sync id="m1"/>Look at this.</text></speech>
                   <head id="n1" lexeme="NOD" start="s1:m1"/>)",
                48, 1);
}

TEST(BmlSpeechSync, ABrowRaiseSyncedByAConstraintStartsWithItsWord) {
  expect_synced(R"(<speech id="s1" start="0.5"><text>Hello. I am here. <sync id="m2"/>Really here.</text></speech>
                   <faceLexeme id="f1" lexeme="RAISE_BROWS"/>
                   <constraint><synchronize><sync ref="s1:m2"/><sync ref="f1:start"/></synchronize></constraint>)",
                31, 2);
}

}  // namespace
}  // namespace fapc

// The one "did you mean" ranking (fapc/codec/did_you_mean.hpp). Distances counted by hand.
#include <gtest/gtest.h>

#include "fapc/codec/did_you_mean.hpp"
#include "fapc/codec/fap_table.hpp"

namespace fapc {
namespace {

TEST(DidYouMean, EditDistance) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("fba", ".fba"), 1u);
  EXPECT_EQ(edit_distance("complie", "compile"), 2u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(DidYouMean, ClosestFirstTiesInCandidateOrder) {
  const std::vector<std::string> kinds = {"fap", "fba", "mp4", "xmt"};
  EXPECT_EQ(closest_names("fbx", kinds, 2), (std::vector<std::string>{"fba", "fap"}));
  EXPECT_EQ(closest_names("fbx", kinds, 3, 1), (std::vector<std::string>{"fba"}));
  EXPECT_EQ(did_you_mean("fsp", {"fps", "profile"}), "; did you mean fps?");
}

TEST(DidYouMean, OnlyPlausibleSlipsAreSuggested) {
  const std::vector<std::string> commands = {"compile", "encode", "decode", "verify", "info"};
  EXPECT_EQ(did_you_mean("complie", commands), "; did you mean compile?");
  EXPECT_EQ(did_you_mean("frobnicate", commands), "");
  EXPECT_EQ(did_you_mean(".fba", {"fap", "fba"}), "; did you mean fba?");
}

TEST(DidYouMean, OrList) {
  EXPECT_EQ(or_list({}), "");
  EXPECT_EQ(or_list({"a"}), "a");
  EXPECT_EQ(or_list({"a", "b", "c"}), "a, b or c");
}

TEST(DidYouMean, FapNamesUseTheSameRanking) {
  EXPECT_EQ(closest_fap_names("opn_jaw", 1).front(), "open_jaw");
  EXPECT_EQ(unknown_fap_message("opn_jaw").rfind("unknown FAP name 'opn_jaw'; did you mean open_jaw, ", 0), 0u);
}

// A name of a million letters costs no more than a short one: only candidates within the search's
// distance of its length are compared (it took 3 s, and printed the whole name, before).
TEST(DidYouMean, ALongNameIsSearchedAndQuotedWithinBounds) {
  EXPECT_EQ(bounded_edit_distance("kitten", "sitting", 3), 3u);
  EXPECT_EQ(bounded_edit_distance("kitten", "sitting", 2), 3u);  // past the bound: bound + 1
  EXPECT_EQ(bounded_edit_distance("a", "abcdefgh", 2), 3u);
  EXPECT_EQ(bounded_edit_distance("complie", "compile", 5), 2u);
  const std::string name(1000000, 'q');
  EXPECT_TRUE(closest_names(name, {"open_jaw", "raise_b_midlip"}).empty());
  EXPECT_EQ(did_you_mean(name, {"open_jaw"}), "");
  EXPECT_EQ(quoted_name(name), "'" + std::string(64, 'q') + "...' (1000000 characters)");
  EXPECT_EQ(quoted_name("jw"), "'jw'");
  EXPECT_EQ(unknown_fap_message(name), "unknown FAP name '" + std::string(64, 'q') + "...' (1000000 characters)");
}

}  // namespace
}  // namespace fapc

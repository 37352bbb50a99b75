// The FAP table against facts checked by hand in docs/fap-table.md's source table.
#include <gtest/gtest.h>

#include <set>

#include "fapc/codec/fap_table.hpp"

namespace fapc {
namespace {

TEST(FapTable, SixtyEightUniqueFapsInOrder) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < fap_table().size(); ++i) {
    EXPECT_EQ(fap_table()[i].number, static_cast<int>(i) + 1);
    names.insert(fap_table()[i].name);
  }
  EXPECT_EQ(names.size(), 68u);
}

TEST(FapTable, GroupsCoverEveryFapOnce) {
  int next = 1;
  for (const FapGroup& g : fap_groups()) {
    EXPECT_EQ(g.first_fap, next);
    for (int fap = g.first_fap; fap <= g.last_fap; ++fap) EXPECT_EQ(find_fap(fap)->group, g.number);
    next = g.last_fap + 1;
  }
  EXPECT_EQ(next, 69);
}

TEST(FapTable, KnownRows) {
  const FapInfo* jaw = find_fap("open_jaw");
  ASSERT_NE(jaw, nullptr);
  EXPECT_EQ(jaw->number, 3);
  EXPECT_EQ(jaw->unit, Fapu::mns);
  EXPECT_FALSE(jaw->bidirectional);
  EXPECT_EQ(jaw->quant_step, 4);
  EXPECT_EQ(jaw->intra_range, 1080);
  EXPECT_EQ(jaw->predictive_range, 360);
  EXPECT_EQ(jaw->legal_max(), 4320);
  EXPECT_EQ(find_fap(63)->legal_max(), 720);     // 680 rounded up to 720 by the decoder
  EXPECT_EQ(find_fap(48)->legal_max(), 316200);  // 1860 x 170
  EXPECT_EQ(find_fap(47)->quant_step, 512);
  EXPECT_EQ(find_fap(23)->unit, Fapu::au);
  EXPECT_EQ(find_fap(68)->name, "pull_r_ear");
  EXPECT_EQ(find_fap(0), nullptr);
  EXPECT_EQ(find_fap(69), nullptr);
}

TEST(FapTable, NamesAndNumbersAsUsersTypeThem) {
  EXPECT_EQ(find_fap_by_name_or_number("head_pitch")->number, 48);
  EXPECT_EQ(find_fap_by_name_or_number("48")->number, 48);
  EXPECT_EQ(find_fap_by_name_or_number("fap48")->number, 48);
  EXPECT_EQ(find_fap_by_name_or_number("FAP48")->number, 48);
  EXPECT_EQ(find_fap_by_name_or_number("fap"), nullptr);
  EXPECT_EQ(find_fap_by_name_or_number("48x"), nullptr);
}

TEST(FapTable, UnknownNamesSuggestTheClosest) {
  EXPECT_EQ(closest_fap_names("opn_jaw").front(), "open_jaw");
  EXPECT_EQ(closest_fap_names("raise_l_i_eyebrw").front(), "raise_l_i_eyebrow");
  EXPECT_EQ(unknown_fap_message("head_pich"),
            "unknown FAP name 'head_pich'; did you mean head_pitch, head_yaw or head_roll?");
}

}  // namespace
}  // namespace fapc

// The bundled tables: they parse, cover what their readers need, and are symmetric where the face
// is (each side's row mirrors the other's: a check independent of how each row was chosen).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "fapc/codec/fap_table.hpp"
#include "fapc/vocabulary/arkit_shapes.hpp"
#include "fapc/vocabulary/fap_side.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "fapc/vocabulary/visemes.hpp"

namespace fapc::vocabulary {
namespace {

TEST(VocabularyTables, BundledTablesParse) {
  for (const auto& [name, kind] :
       {std::pair{"au_faps.tsv", TableKind::action_units}, std::pair{"arkit_faps.tsv", TableKind::arkit_shapes}}) {
    Result<MappingTable> parsed = parse_mapping_table(bundled_table_text(name), name, kind);
    ASSERT_TRUE(parsed.ok()) << format_diagnostic(parsed.error());
    EXPECT_FALSE(parsed->rows.empty());
  }
  Result<std::vector<VisemeRow>> visemes = parse_viseme_table(bundled_table_text("visemes.tsv"), "visemes.tsv");
  ASSERT_TRUE(visemes.ok()) << format_diagnostic(visemes.error());
  EXPECT_EQ(action_unit_table().rows.size(),
            parse_mapping_table(bundled_table_text("au_faps.tsv"), "x", TableKind::action_units)->rows.size());
}

// The 17 intensities OpenFace 2.0 writes (AUxx_r), and the head and eye units a BML script names.
TEST(VocabularyTables, ActionUnitsCoverOpenFaceAndHeadAndEyes) {
  const MappingTable& table = action_unit_table();
  for (int au :
       {1, 2, 4, 5, 6, 7, 9, 10, 12, 14, 15, 17, 20, 23, 25, 26, 45, 28, 51, 52, 53, 54, 55, 56, 61, 62, 63, 64}) {
    EXPECT_TRUE(table.has_key(std::to_string(au))) << "AU" << au;
    EXPECT_FALSE(table.is_lost(std::to_string(au))) << "AU" << au;
  }
  EXPECT_TRUE(table.is_lost("57"));
  EXPECT_TRUE(table.is_lost("58"));
}

TEST(VocabularyTables, EveryArkitShapeHasRows) {
  const MappingTable& table = arkit_table();
  EXPECT_EQ(table.keys().size(), 52u);
  for (std::string_view shape : arkit_shape_names()) EXPECT_TRUE(table.has_key(shape)) << shape;
}

// The mirror image of a FAP's movement: the partner FAP (mirror_fap) with the same value, except
// where both name the same side as positive (the eyeball yaws 23/24 turn both eyes to the face's
// left; a middle FAP such as shift_jaw is its own partner): a leftward move mirrors to a
// rightward one, so the sign flips.
double mirrored_amount(int fap, double amount) {
  const std::string_view way = fap_table()[static_cast<std::size_t>(fap - 1)].positive_motion;
  const std::string_view partner_way = fap_table()[static_cast<std::size_t>(mirror_fap(fap) - 1)].positive_motion;
  const bool lateral = way == "left" || way == "right";
  return lateral && way == partner_way ? -amount : amount;
}

std::map<int, double> faps_of(const MappingTable& table, const std::string& key) {
  std::map<int, double> out;
  for (const MappingRow& row : table.rows_of(key)) out[row.fap] = row.amount;
  return out;
}

void expect_mirrors(const std::map<int, double>& a, const std::map<int, double>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (const auto& [fap, amount] : a) {
    const auto it = b.find(mirror_fap(fap));
    ASSERT_NE(it, b.end()) << what << ": FAP " << fap << " has no mirror " << mirror_fap(fap);
    EXPECT_EQ(it->second, mirrored_amount(fap, amount)) << what << ": FAP " << fap;
  }
}

TEST(VocabularyTables, ArkitLeftAndRightShapesMirror) {
  int pairs = 0;
  for (std::string_view shape : arkit_shape_names()) {
    const std::string name(shape);
    if (!name.ends_with("Left")) continue;
    const std::string other = name.substr(0, name.size() - 4) + "Right";
    ASSERT_TRUE(find_arkit_shape(other)) << other;
    expect_mirrors(faps_of(arkit_table(), name), faps_of(arkit_table(), other), name);
    ++pairs;
  }
  EXPECT_EQ(pairs, 20);  // 7 eye, 7 lip, 2 brow, cheek, nose, jaw and mouth pairs
}

// Action units of both sides (all but the head and eye turns, which move one way, and 57/58)
// move each side as its mirror does.
TEST(VocabularyTables, BilateralActionUnitsAreSymmetric) {
  const MappingTable& table = action_unit_table();
  for (const std::string& key : table.keys()) {
    const int au = std::stoi(key);
    if (au >= 51) continue;
    expect_mirrors(faps_of(table, key), faps_of(table, key), "AU" + key);
  }
}

TEST(VocabularyTables, FapSidesComeFromTheNames) {
  EXPECT_EQ(fap_side(3), Side::middle);
  EXPECT_EQ(fap_side(6), Side::left);
  EXPECT_EQ(fap_side(7), Side::right);
  EXPECT_EQ(fap_side(10), Side::left);    // raise_b_lip_lm
  EXPECT_EQ(fap_side(58), Side::right);   // raise_b_lip_rm_o
  EXPECT_EQ(fap_side(31), Side::left);    // raise_l_i_eyebrow
  EXPECT_EQ(fap_side(48), Side::middle);  // head_pitch
  EXPECT_EQ(fap_side(63), Side::middle);  // raise_nose
  int sided = 0;
  for (int fap = 3; fap <= kFapCount; ++fap) {
    const int other = mirror_fap(fap);
    EXPECT_EQ(mirror_fap(other), fap) << fap;
    if (fap_side(fap) == Side::middle) {
      EXPECT_EQ(other, fap);
      continue;
    }
    ++sided;
    EXPECT_NE(fap_side(other), fap_side(fap)) << fap;
    EXPECT_NE(fap_side(other), Side::middle) << fap;
  }
  // Counted by hand from docs/fap-table.md: every FAP of 3-68 is paired except 3-5, 14-18,
  // 43-50, 51, 52 and 63-64.
  EXPECT_EQ(sided, 66 - 20);
}

TEST(VocabularyTables, ArkitNamesInBothCases) {
  EXPECT_EQ(find_arkit_shape("eyeBlinkLeft"), 0);
  EXPECT_EQ(find_arkit_shape("EyeBlinkLeft"), 0);
  EXPECT_EQ(find_arkit_shape("TongueOut"), 51);
  EXPECT_FALSE(find_arkit_shape("_neutral"));
  EXPECT_FALSE(find_arkit_shape("eyeblinkleft"));
  EXPECT_EQ(pascal_case("mouthSmileLeft"), "MouthSmileLeft");
  std::set<std::string_view> distinct(arkit_shape_names().begin(), arkit_shape_names().end());
  EXPECT_EQ(distinct.size(), 52u);
}

// The Oculus / OpenXR viseme names, written here from that set's documentation in its order.
TEST(VocabularyTables, VisemesMatchTheOpenXrSetInOrder) {
  const char* expected[] = {"sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS", "nn", "RR", "aa", "E", "ih", "oh", "ou"};
  ASSERT_EQ(viseme_table().size(), 15u);
  for (int v = 0; v < 15; ++v) {
    EXPECT_EQ(openxr_viseme_name(v), expected[v]);
    EXPECT_EQ(viseme_from_openxr(expected[v]), v);
    EXPECT_EQ(viseme_table()[static_cast<std::size_t>(v)].mpeg4, viseme_name(v));
  }
  EXPECT_FALSE(viseme_from_openxr("AA"));
  EXPECT_EQ(openxr_viseme_name(15), "");
}

}  // namespace
}  // namespace fapc::vocabulary

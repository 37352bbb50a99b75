// Malformed .fap inputs and the exact diagnostic each must produce (position and message were
// worked out by hand from the input text; the caret column is the offending token's first byte).
#include <gtest/gtest.h>

#include "fapc/codec/fap_file.hpp"

namespace fapc {
namespace {

std::string mask_with(std::initializer_list<int> on, int tokens = 68) {
  std::string out;
  for (int i = 1; i <= tokens; ++i) {
    bool set = false;
    for (int fap : on) set = set || fap == i;
    out += (i > 1 ? " " : "") + std::string(set ? "1" : "0");
  }
  return out;
}

const std::string kJaw = mask_with({3});          // FAP 3 only; 135 characters
const std::string kJawHead = mask_with({3, 48});  // FAPs 3 and 48
const std::string kViseme = mask_with({1, 3});    // FAP 1 and FAP 3

struct BadCase {
  const char* name;
  std::string text;
  std::string expected;  // format_diagnostic of the error
};

std::vector<BadCase> bad_cases() {
  return {
      {"fps-not-a-number", "2.1 demo fast 1\n" + kJaw + "\n0 1\n",
       "bad.fap:1:10: error: header frame rate must be a number from 1 to 1000, found 'fast'"},
      {"fps-zero", "2.1 demo 0 1\n" + kJaw + "\n0 1\n",
       "bad.fap:1:10: error: header frame rate must be a number from 1 to 1000, found '0'"},
      {"fps-rounds-to-zero", "2.1 demo .1 1\n" + kJaw + "\n0 1\n",  // found by the fuzzer
       "bad.fap:1:10: error: header frame rate must be a number from 1 to 1000, found '.1'"},
      {"count-negative", "2.1 demo 25 -1\n" + kJaw + "\n0 1\n",
       "bad.fap:1:13: error: header frame count must be a non-negative integer, found '-1'"},
      {"count-float", "2.1 demo 25 2.5\n" + kJaw + "\n0 1\n",
       "bad.fap:1:13: error: header frame count must be a non-negative integer, found '2.5'"},
      {"mask-too-short", "2.1 demo 25 1\n0 0 1\n0 1\n",
       "bad.fap:2:6: error: mask line has 3 values; expected 68 (one 0 or 1 per FAP)"},
      {"mask-70-tokens", "2.1 demo 25 1\n" + kJaw + " 0 0\n0 1\n",
       "bad.fap:2:137: error: mask line has 70 values; expected 68 (one 0 or 1 per FAP)"},
      {"mask-69th-is-one", "2.1 demo 25 1\n" + kJaw + " 1\n0 1\n",
       "bad.fap:2:137: error: mask line has 69 values; expected 68 (one 0 or 1 per FAP)"},
      {"mask-value-two", "2.1 demo 25 1\n0 0 2" + kJaw.substr(5) + "\n0 1\n",
       "bad.fap:2:5: error: mask value for FAP 3 must be 0 or 1, found '2'"},
      {"mask-value-word", "2.1 demo 25 1\nx" + kJaw.substr(1) + "\n0 1\n",
       "bad.fap:2:1: error: mask value for FAP 1 must be 0 or 1, found 'x'"},
      {"frame-number-word", "2.1 demo 25 1\n" + kJaw + "\nzero 1\n",
       "bad.fap:3:1: error: a value line must start with an integer frame number, found 'zero'"},
      {"frame-number-float", "2.1 demo 25 1\n" + kJaw + "\n0.5 1\n",
       "bad.fap:3:1: error: a value line must start with an integer frame number, found '0.5'"},
      {"too-few-values", "2.1 demo 25 1\n" + kJawHead + "\n0 1\n",
       "bad.fap:3:4: error: value line has 1 values after the frame number; its mask needs 2"},
      {"too-many-values", "2.1 demo 25 1\n" + kJaw + "\n0 1 2 3\n",
       "bad.fap:3:5: error: value line has 3 values after the frame number; its mask needs 1"},
      {"viseme-neither-form", "2.1 demo 25 1\n" + kViseme + "\n0 1 2 3\n",
       "bad.fap:3:8: error: value line has 3 values after the frame number; its mask needs 5 "
       "(FAP 1 as 4 and FAP 2 as 6 values) or 2 (one value each)"},
      {"value-not-a-number", "2.1 demo 25 1\n" + kJaw + "\n0 abc\n",
       "bad.fap:3:3: error: value of FAP 3 must be a number, found 'abc'"},
      {"value-overflows", "2.1 demo 25 1\n" + kJaw + "\n0 99999999999\n",
       "bad.fap:3:3: error: value of FAP 3 99999999999 is outside -2147483647..2147483647"},
      {"viseme-select-out-of-range", "2.1 demo 25 1\n" + kViseme + "\n0 15 0 0 0 7\n",
       "bad.fap:3:3: error: viseme_select1 15 is outside 0..14"},
      {"viseme-blend-out-of-range", "2.1 demo 25 1\n" + kViseme + "\n0 1 2 64 0 7\n",
       "bad.fap:3:7: error: viseme_blend 64 is outside 0..63"},
      {"mask-without-values", "2.1 demo 25 1\n" + kJaw + "\n",
       "bad.fap:2:136: error: mask line without the value line that must follow it"},
      {"frames-descending", "2.1 demo 25 2\n" + kJaw + "\n1 5\n" + kJaw + "\n0 6\n",
       "bad.fap:5:1: error: frame number 0 does not follow frame 1; frame numbers must ascend"},
      {"frames-duplicated", "2.1 demo 25 2\n" + kJaw + "\n0 5\n" + kJaw + "\n0 6\n",
       "bad.fap:5:1: error: frame number 0 does not follow frame 0; frame numbers must ascend"},
      // The smallest gap (30 ms) does not divide a second, so SEMAINE's 40 ms grid is assumed.
      {"stamps-off-grid", "280\n" + kJaw + "\n320 1\n" + kJaw + "\n360 1\n" + kJaw + "\n390 1\n",
       "bad.fap:7:1: error: time stamp 390 ms is not on the 40 ms grid of the first frame"},
      {"header-like-garbage", "hello world foo bar\n",
       "bad.fap:1:20: error: mask line has 4 values; expected 68 (one 0 or 1 per FAP)"},
      {"binary-junk", std::string("2.1 demo 25 1\n\x01\x02\x03\n0 1\n", 22),
       "bad.fap:2:4: error: mask line has 1 values; expected 68 (one 0 or 1 per FAP)"},
  };
}

TEST(FapMalformed, EachInputGetsItsExactDiagnostic) {
  const auto cases = bad_cases();
  ASSERT_GE(cases.size(), 20u);
  for (const BadCase& c : cases) {
    auto read = read_fap_text(c.text, "bad.fap");
    ASSERT_FALSE(read.ok()) << c.name << " was accepted";
    EXPECT_EQ(format_diagnostic(read.error()), c.expected) << c.name;
    EXPECT_FALSE(read.error().source_line.empty()) << c.name << ": no source line for the caret";
  }
}

TEST(FapMalformed, CaretPointsAtTheColumn) {
  auto read = read_fap_text("2.1 demo fast 1\n", "bad.fap");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(render_with_caret(read.error()),
            "bad.fap:1:10: error: header frame rate must be a number from 1 to 1000, found 'fast'\n"
            "2.1 demo fast 1\n"
            "         ^");
}

}  // namespace
}  // namespace fapc

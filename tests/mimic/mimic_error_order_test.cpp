// Programs with more than one error: main is compiled while it is parsed, yet the error reported
// is the one the compiler gave when it checked the whole parsed program (a syntax error anywhere;
// then the definitions, a macro too big, main too big; then the first other error in source
// order). Each expected diagnostic was produced by that earlier compiler (main at c00aeff, which
// parsed everything before checking anything) and read by hand.
#include "mimic_test_support.hpp"

namespace fapc {
namespace {

std::string error_with_runs(const std::string& source, std::int64_t max_runs) {
  MimicOptions options;
  options.max_runs = max_runs;
  Result<MimicProgram> program = compile_mimic(source, "t.mimic", options);
  EXPECT_FALSE(program.ok()) << "compiled: " << source;
  return program.ok() ? std::string() : render_with_caret(program.error());
}

// The diagnostic's first line only: where and what.
std::string first_line(const std::string& diagnostic) { return diagnostic.substr(0, diagnostic.find('\n')); }

TEST(MimicErrorOrder, ASyntaxErrorLaterWinsOverAnEarlierCheck) {
  EXPECT_EQ(first_line(test::error_of("main { jw <hold=1,value=1>; { jaw <hold=1,value=1>; }")),
            "t.mimic:1:6: error: this '{' is never closed");
  // Even over a definition defined twice.
  EXPECT_EQ(first_line(test::error_of("def m { jaw <hold=1,value=1>; } def m { jaw <hold=1,value=1>; } "
                                      "main { jw <hold=1,value=1>; { jaw }")),
            "t.mimic:1:70: error: this '{' is never closed");
}

TEST(MimicErrorOrder, ChecksComeBeforeScheduling) {
  // The first action starts before 0 (a scheduling error); the second is unknown (a check).
  EXPECT_EQ(first_line(test::error_of("main { jaw <left=-1,hold=1,value=1>; jw <hold=1,value=1>; }")),
            "t.mimic:1:38: error: unknown animation parameter 'jw'; did you mean jaw, open_jaw, shift_jaw?");
}

TEST(MimicErrorOrder, MacroBodiesAndMainsParametersComeBeforeMain) {
  EXPECT_EQ(first_line(test::error_of("def m { jw <hold=1,value=1>; } main { jaw <hold=1,value=1>; }")),
            "t.mimic:1:9: error: unknown animation parameter 'jw'; did you mean jaw, open_jaw, shift_jaw?");
  EXPECT_EQ(first_line(test::error_of("main <in=1> { jw <hold=1,value=1>; }")),
            "t.mimic:1:7: error: 'in' applies to atomic actions, not to main");
}

TEST(MimicErrorOrder, MainTooBigWinsOverAnEarlierCheck) {
  const std::string too_many =
      ": error: the program has too many actions with macros expanded: more than the limit of ";
  // Nodes counted in source order: main, jw, jaw, the parallel, and its jaw is the fifth.
  EXPECT_EQ(
      first_line(error_with_runs("main { jw <hold=1,value=1>; jaw <hold=1,value=1>; [ jaw <hold=1,value=1>; ] }", 3)),
      "t.mimic:1:53" + too_many + "3 runs (--max-runs N raises it)");
  // Over the check of an unused macro's body too.
  EXPECT_EQ(first_line(error_with_runs("def m { jw <hold=1,value=1>; } main { jaw <hold=1,value=1>; "
                                       "jaw <hold=1,value=1>; jaw <hold=1,value=1>; }",
                                       3)),
            "t.mimic:1:83" + too_many + "3 runs (--max-runs N raises it)");
  // Where the count passes inside a macro's body, the error points into the body.
  EXPECT_EQ(first_line(error_with_runs("def m { jaw <hold=1,value=1>; jaw <hold=1,value=1>; } "
                                       "main { jaw <hold=1,value=1>; { m; m; } }",
                                       6)),
            "t.mimic:1:31" + too_many + "6 runs (--max-runs N raises it)");
  // A macro too big is named at its own group, before main is looked at.
  EXPECT_EQ(first_line(error_with_runs("def m { jaw <hold=1,value=1>; jaw <hold=1,value=1>; jaw <hold=1,value=1>; "
                                       "jaw <hold=1,value=1>; } main { jw <hold=1,value=1>; m; }",
                                       4)),
            "t.mimic:1:7" + too_many + "4 runs (--max-runs N raises it)");
  // Main fits, but with the macro bodies' own checks the actions built pass the limit.
  EXPECT_EQ(first_line(error_with_runs("def m { jaw <hold=1,value=1>; jaw <hold=1,value=1>; } "
                                       "main { jaw <hold=1,value=1>; jaw <hold=1,value=1>; }",
                                       5)),
            "t.mimic:1:84" + too_many + "5 runs (--max-runs N raises it)");
}

}  // namespace
}  // namespace fapc

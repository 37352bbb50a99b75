// Inputs written to break fapc (issue 13), generated here rather than stored: nesting deeper than
// any stack, include cycles, includes that reach outside the input's folder, and a folder or FIFO
// where a file is expected. Each must end in exit status 1 with a positioned error that names the
// rule, no output and no signal, quickly.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

class HostileInputs : public ::testing::Test {
 protected:
  fs::path dir;

  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::path(test::binary_dir()) / "hostile-inputs" / info->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }

  std::string at(const std::string& name) const { return (dir / name).string(); }

  std::string write(const std::string& name, const std::string& text) const {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name, std::ios::binary) << text;
    return at(name);
  }

  // fapc ARGS, expected to fail with exit 1 and `expected` in its standard error, within 10 s and
  // without writing `output`.
  std::string refused(const std::string& args, const std::string& expected, const std::string& output = "") const {
    if (!output.empty()) fs::remove(output);
    const auto start = std::chrono::steady_clock::now();
    const test::CommandRun run = test::run_fapc(args);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(run.exit_status, 1) << args << "\n" << run.err;
    EXPECT_NE(run.err.find(expected), std::string::npos) << args << "\nexpected: " << expected << "\ngot: " << run.err;
    EXPECT_LT(seconds, 10) << args;
    if (!output.empty()) {
      EXPECT_FALSE(fs::exists(output)) << output;
    }
    return run.err;
  }

  void refused_everywhere(const std::string& name, const std::string& why) const;
};

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

// A small valid .fap: the bundled example.
std::string fap_text() { return test::read_text(test::corpus_dir() + "/examples/fap/joy.fap"); }

// ---- depth limits (docs/security.md, "Depth limits") -------------------------------------------

TEST_F(HostileInputs, AlgebraParenthesesDeeperThanTheLimit) {
  write("a.fap", fap_text());
  const std::string deep = repeat("(", 10000) + "a.fap" + repeat(")", 10000);
  refused("combine '" + deep + "' -o " + at("out.fap"),
          "<expression>:1:257: error: parentheses and amplifiers nested deeper than 256 levels", at("out.fap"));
  write("deep.combine", "# deep\n" + deep + "\n");
  refused("compile " + at("deep.combine") + " -o " + at("out.fap"),
          "deep.combine:2:257: error: parentheses and amplifiers nested deeper than 256 levels", at("out.fap"));
  // An amplifier recurses like a parenthesis: 2 * 2 * ... * a.fap.
  refused("combine '" + repeat("2 * ", 10000) + "a.fap' -o " + at("out.fap"),
          "nested deeper than 256 levels (the depth limit)", at("out.fap"));
  // 256 levels are allowed.
  const std::string limit = repeat("(", 256) + at("a.fap") + repeat(")", 256);
  EXPECT_EQ(test::run_fapc("combine '" + limit + "' -o " + at("ok.fap")).exit_status, 0);
}

TEST_F(HostileInputs, MimicGroupsDeeperThanTheLimit) {
  write("deep.mimic", "main " + repeat("{", 5000) + " open_jaw <in=1,value=100>; " + repeat("}", 5000) + "\n");
  refused("compile " + at("deep.mimic") + " -o " + at("out.fap"),
          "deep.mimic:1:262: error: groups nested deeper than 256 levels (the depth limit)", at("out.fap"));
  // A chain of macros, each one group deep, nests as deep as the chain.
  std::string chain = "def m0 { open_jaw <in=1,value=100>; }\n";
  for (int i = 1; i <= 2000; ++i) chain += "def m" + std::to_string(i) + " { m" + std::to_string(i - 1) + "; }\n";
  write("chain.mimic", chain + "main { m2000; }\n");
  refused("compile " + at("chain.mimic") + " -o " + at("out.fap"),
          "groups (with macros expanded) nested deeper than 256 levels (the depth limit)", at("out.fap"));
}

TEST_F(HostileInputs, MimicMacrosThatDoubleAreRefused) {
  std::string program = "def m0 { open_jaw <in=1,value=100>; }\n";
  for (int i = 1; i <= 40; ++i) {
    program += "def m" + std::to_string(i) + " { m" + std::to_string(i - 1) + "; m" + std::to_string(i - 1) + "; }\n";
  }
  write("double.mimic", program + "main { m40; }\n");
  refused("compile " + at("double.mimic") + " -o " + at("out.fap"),
          "error: the program has too many actions with macros expanded: more than the limit of 4000000 runs",
          at("out.fap"));
}

TEST_F(HostileInputs, FmlTemplateChainsDeeperThanTheLimit) {
  // Each template one level deep, each using the one before: 20000 levels once expanded.
  std::string model = "<template name=\"t0\"><expr type=\"smile\" val=\"60\" duration=\"0.5s\"/></template>";
  for (int i = 1; i < 20000; ++i) {
    model += "<template name=\"t" + std::to_string(i) + "\"><seq><behavior name=\"t" + std::to_string(i - 1) +
             "\"/></seq></template>";
  }
  write("chain.fml",
        "<fml><model>" + model + "</model><story><action><behavior name=\"t19999\"/></action></story></fml>\n");
  refused("compile " + at("chain.fml") + " -o " + at("out.fap"),
          "error: elements (with templates expanded) nested deeper than 256 levels (the depth limit)", at("out.fap"));
}

TEST_F(HostileInputs, XmlElementsDeeperThanTheLimitInCompileAndValidate) {
  const std::string deep = "<?xml version=\"1.0\"?>\n<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\"><body>" +
                           repeat("<par>", 100000) + repeat("</par>", 100000) + "</body></XMT-O>\n";
  write("deep.xmt", deep);
  // The 257th level: <XMT-O> and <body> are two of them, so the 255th <par> at column 1324.
  const std::string expected = "deep.xmt:2:1324: error: elements nested deeper than 256 levels (the depth limit)";
  refused("compile " + at("deep.xmt") + " -o " + at("out.fap"), expected, at("out.fap"));
  refused("validate " + at("deep.xmt"), expected);
  write("deep.fml", "<fml><story>" + repeat("<seq>", 100000) + repeat("</seq>", 100000) + "</story></fml>\n");
  refused("compile " + at("deep.fml") + " -o " + at("out.fap"), "nested deeper than 256 levels", at("out.fap"));
}

// Xerces-C's regular expressions recurse once per list item: 3 * 10^5 items crashed validate even
// on a 256 MB stack. The list's form is checked in code (docs/schemas/xmt-o.xsd, NumberList).
TEST_F(HostileInputs, ValidateTakesALongValuesList) {
  std::string values;
  for (int i = 0; i < 300000; ++i) values += (i ? ";" : "") + std::to_string(i % 300);
  write("values.xmt",
        "<?xml version=\"1.0\"?>\n<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\">\n  <body>\n"
        "    <animate attributeName=\"open_jaw\" values=\"" +
            values +
            "\" dur=\"100s\"/>\n"
            "  </body>\n</XMT-O>\n");
  const test::CommandRun run = test::run_fapc("validate " + at("values.xmt"));
  EXPECT_EQ(run.exit_status, 0) << run.err;
  EXPECT_NE(run.out.find("valid XMT-Omega"), std::string::npos) << run.out;
}

TEST_F(HostileInputs, ValidateChecksTheFormOfNumberLists) {
  write("bad.xmt",
        "<?xml version=\"1.0\"?>\n<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\">\n  <body>\n"
        "    <animate attributeName=\"open_jaw\" values=\"1;;2\" keyTimes=\"0;1e\" dur=\"1s\"/>\n"
        "  </body>\n</XMT-O>\n");
  const std::string err = refused("validate " + at("bad.xmt"),
                                  "bad.xmt:4:39: error: 'values': '1;;2' is not a list of numbers separated by ';'");
  EXPECT_NE(err.find("bad.xmt:4:53: error: 'keyTimes': '0;1e' is not a list of numbers separated by ';'"),
            std::string::npos)
      << err;
  write("good.xmt",
        "<?xml version=\"1.0\"?>\n<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\">\n  <body>\n"
        "    <animate attributeName=\"open_jaw\" values=\" +1.5e2 ; -.5;0.; \" keyTimes=\"0;0.5;1\" dur=\"1s\"/>\n"
        "  </body>\n</XMT-O>\n");
  EXPECT_EQ(test::run_fapc("validate " + at("good.xmt")).exit_status, 0);
}

// ---- include cycles ----------------------------------------------------------------------------

TEST_F(HostileInputs, CombineFilesThatIncludeThemselves) {
  write("self.combine", "self.combine\n");
  refused("compile " + at("self.combine") + " -o " + at("out.fap"),
          at("self.combine") + ":1:1: error: include cycle: " + at("self.combine") + " -> " + at("self.combine"),
          at("out.fap"));
  write("a.combine", "# a\nb.combine * 2\n");
  write("b.combine", "0.5 * a.combine\n");
  refused("compile " + at("a.combine") + " -o " + at("out.fap"),
          at("b.combine") + ":1:7: error: include cycle: " + at("a.combine") + " -> " + at("b.combine") + " -> " +
              at("a.combine"),
          at("out.fap"));
}

TEST_F(HostileInputs, CyclesAcrossFormats) {
  // An XMT-Omega document that places a .combine whose operand is the document again.
  write("doc.xmt", "<XMT-O><body><animation src=\"loop.combine\"/></body></XMT-O>\n");
  write("loop.combine", "doc.xmt\n");
  refused(
      "compile " + at("doc.xmt") + " -o " + at("out.fap"),
      "loop.combine:1:1: error: include cycle: " + at("doc.xmt") + " -> " + at("loop.combine") + " -> " + at("doc.xmt"),
      at("out.fap"));
}

TEST_F(HostileInputs, IncludesNestedDeeperThanTheLimit) {
  write("a.fap", fap_text());
  write("c0.combine", "a.fap\n");
  for (int i = 1; i <= 20; ++i) write("c" + std::to_string(i) + ".combine", "c" + std::to_string(i - 1) + ".combine\n");
  refused("compile " + at("c20.combine") + " -o " + at("out.fap"),
          "inputs included more than 16 levels deep (the include depth limit)", at("out.fap"));
  EXPECT_EQ(test::run_fapc("compile " + at("c10.combine") + " -o " + at("ok.fap")).exit_status, 0);
}

// ---- includes stay in the input's folder (docs/security.md, "Includes") -----------------------

TEST_F(HostileInputs, DefxprCannotReadOutsideTheProgramsFolder) {
  write("m/x.mimic", "defxpr e \"/etc/passwd\" main { e <in=1,value=1>; }\n");
  const std::string err = refused("compile " + at("m/x.mimic") + " -o " + at("out.fap"),
                                  "x.mimic:1:10: error: '/etc/passwd' is an absolute path outside the folders a "
                                  "script may include from",
                                  at("out.fap"));
  EXPECT_EQ(err.find("root:"), std::string::npos) << "no line of the file is shown";
  write("secret.xpr", "open_jaw 100\n");
  write("m/y.mimic", "defxpr e \"../secret.xpr\" main { e <in=1,value=1>; }\n");
  refused("compile " + at("m/y.mimic") + " -o " + at("out.fap"), "'../secret.xpr' leads outside the folders",
          at("out.fap"));
  // A symbolic link inside the folder that points outside it is an escape too.
  fs::create_symlink(at("secret.xpr"), at("m/link.xpr"));
  write("m/z.mimic", "defxpr e \"link.xpr\" main { e <in=1,value=1>; }\n");
  refused("compile " + at("m/z.mimic") + " -o " + at("out.fap"), "'link.xpr' leads outside the folders", at("out.fap"));
  // --allow-include opens a folder.
  const test::CommandRun allowed =
      test::run_fapc("compile " + at("m/y.mimic") + " -o " + at("ok.fap") + " --allow-include " + dir.string());
  EXPECT_EQ(allowed.exit_status, 0) << allowed.err;
}

TEST_F(HostileInputs, EveryIncludeMechanismFollowsThePolicy) {
  write("outside.fap", fap_text());
  write("outside.pho", "_ 100\n");
  write("in/a.combine", "../outside.fap\n");
  refused("compile " + at("in/a.combine") + " -o " + at("out.fap"), "'../outside.fap' leads outside", at("out.fap"));
  write("in/a.xmt", "<XMT-O><body><animation src=\"../outside.fap\"/></body></XMT-O>\n");
  refused("compile " + at("in/a.xmt") + " -o " + at("out.fap"), "'../outside.fap' leads outside", at("out.fap"));
  write("in/a.fml", "<fml><story><talk file=\"../outside.pho\"/></story></fml>\n");
  refused("compile " + at("in/a.fml") + " -o " + at("out.fap"), "'../outside.pho' leads outside", at("out.fap"));
  // An included input's own includes stay inside the top input's tree, not its own.
  write("in/sub/b.combine", "../../outside.fap\n");
  write("in/c.combine", "sub/b.combine\n");
  refused("compile " + at("in/c.combine") + " -o " + at("out.fap"), "'../../outside.fap' leads outside", at("out.fap"));
  write("in/sub/d.combine", "../e.fap\n");
  write("in/e.fap", fap_text());
  write("in/f.combine", "sub/d.combine\n");
  EXPECT_EQ(test::run_fapc("compile " + at("in/f.combine") + " -o " + at("ok.fap")).exit_status, 0);
}

TEST_F(HostileInputs, StandardInputIncludesFromTheWorkingFolder) {
  write("s/smile.xpr", "open_jaw 100\n");
  const test::CommandRun run =
      test::run_shell("cd '" + at("s") + "' && echo 'defxpr e \"smile.xpr\" main { e <in=1,value=1>; }' | '" +
                      test::fapc_program() + "' compile - --from mimic -o out.fap");
  EXPECT_EQ(run.exit_status, 0) << run.err;
  const test::CommandRun escape =
      test::run_shell("cd '" + at("s") + "' && echo 'defxpr e \"../x.xpr\" main { e <in=1,value=1>; }' | '" +
                      test::fapc_program() + "' compile - --from mimic -o out2.fap");
  EXPECT_EQ(escape.exit_status, 1);
  EXPECT_NE(escape.err.find("'../x.xpr' leads outside the folders a script may include from ('.')"), std::string::npos)
      << escape.err;
}

// ---- a folder or FIFO where a file is expected -------------------------------------------------

// NAME.fap, NAME.xpr and NAME.pho, made by the caller as something other than a file, given as
// the input, as --profile and through every include mechanism: each refused with `why`, placed at
// the include that names it.
void HostileInputs::refused_everywhere(const std::string& name, const std::string& why) const {
  const std::string out = at("out.fap");
  refused("compile " + at(name + ".fap") + " -o " + out, at(name + ".fap") + ": error: " + why, out);
  write("ok.mimic", "main { open_jaw <in=1,value=100>; }\n");
  refused("compile " + at("ok.mimic") + " -o " + out + " --profile " + at(name + ".fap"), why, out);
  write("x.mimic", "defxpr e \"" + name + ".xpr\" main { e <in=1,value=1>; }\n");
  refused("compile " + at("x.mimic") + " -o " + out,
          "x.mimic:1:10: error: cannot read the expression file '" + name + ".xpr': " + why, out);
  write("x.xmt", "<XMT-O><body><animation src=\"" + name + ".fap\"/></body></XMT-O>\n");
  refused("compile " + at("x.xmt") + " -o " + out,
          "x.xmt:1:25: error: cannot place '" + at(name + ".fap") + "': " + why, out);
  write("x.combine", name + ".fap\n");
  refused("compile " + at("x.combine") + " -o " + out, why, out);
  write("x.fml", "<fml><story><talk file=\"" + name + ".pho\"/></story></fml>\n");
  refused("compile " + at("x.fml") + " -o " + out, "x.fml:1:19: error: talk file '" + name + ".pho': " + why, out);
  refused("validate " + at(name + ".fap"), why);
  refused("combine " + at(name + ".fap") + " -o " + out, why, out);
}

TEST_F(HostileInputs, FoldersWhereAFileIsExpected) {
  for (const char* name : {"d.fap", "d.xpr", "d.pho"}) fs::create_directories(at(name));
  refused_everywhere("d", "is a directory");
}

TEST_F(HostileInputs, FifosNeverBlock) {
  for (const char* name : {"f.fap", "f.xpr", "f.pho"}) ASSERT_EQ(::mkfifo(at(name).c_str(), 0600), 0);
  refused_everywhere("f", "not a regular file (a FIFO)");
}

TEST_F(HostileInputs, UnreadableFiles) {
  // Permission bits do not stop root, and the tests may run as root: then there is nothing to see.
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: a file without read permission is still readable";
  write("secret.fap", fap_text());
  fs::permissions(at("secret.fap"), fs::perms::none);
  refused("compile " + at("secret.fap") + " -o " + at("out.fap"), "cannot open file: Permission denied", at("out.fap"));
}

}  // namespace
}  // namespace fapc

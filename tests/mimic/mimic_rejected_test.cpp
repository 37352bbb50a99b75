// Rejected programs with their exact diagnostics (rejected_programs.txt, checked by hand).
#include <sstream>

#include "mimic_test_support.hpp"

namespace fapc {
namespace {

struct Case {
  std::string source;
  std::string expected;
};

std::vector<Case> read_cases() {
  std::istringstream in(test::read_text(test::source_dir() + "/tests/mimic/rejected_programs.txt"));
  std::vector<Case> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("SRC ", 0) == 0) {
      cases.push_back(Case{line.substr(4), {}});
    } else if (!cases.empty() && !line.empty()) {
      cases.back().expected += line + "\n";
    }
  }
  return cases;
}

TEST(MimicRejected, EveryProgramFailsWithItsDiagnostic) {
  const std::vector<Case> cases = read_cases();
  ASSERT_GE(cases.size(), 40u);
  const std::map<std::string, std::string> files{{"s.xpr", "# s\nraise_l_cornerlip 100\nsmyle 3\n"}};
  for (const Case& c : cases) {
    // render_with_caret ends without a newline after the caret; the file has one.
    EXPECT_EQ(test::error_of(c.source, files) + "\n", c.expected) << c.source;
  }
}

}  // namespace
}  // namespace fapc

// The repository explains itself: every document a comment or a doc cites is in the repository,
// every section it cites exists there, and every short tag (V1-V17 of the .fap variants, D1-D10
// and E9-E12 of the reference FBA codec, "Mimic Table 1" and the like for the papers) is defined
// once in docs/, where a reader who greps the tag finds it. The rules are in docs/testing.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

// One file's text as a reader sees it: the comments of C++ sources, the whole text of anything
// else, with line breaks and comment leaders turned into single spaces so that a citation broken
// over two lines is still one match. `line_at` maps an offset back to its line.
struct Prose {
  std::string text;
  std::vector<std::pair<std::size_t, int>> line_starts;  // (offset in text, line number)

  int line_at(std::size_t offset) const {
    auto it = std::upper_bound(line_starts.begin(), line_starts.end(), std::make_pair(offset, 1 << 30));
    return it == line_starts.begin() ? 1 : std::prev(it)->second;
  }
};

bool is_cpp(const std::string& path) {
  for (const char* ext : {".cpp", ".hpp", ".h", ".cc"})
    if (path.ends_with(ext)) return true;
  return false;
}

Prose prose_of(const std::string& path, const std::string& content) {
  Prose prose;
  std::istringstream lines(content);
  std::string line;
  bool in_block_comment = false;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::string part;
    if (is_cpp(path)) {
      // Comment text only: after "//", or inside /* */. Code and string literals are not prose.
      std::size_t at = 0;
      while (at < line.size()) {
        if (in_block_comment) {
          const auto end = line.find("*/", at);
          part += line.substr(at, end == std::string::npos ? std::string::npos : end - at) + " ";
          if (end == std::string::npos) break;
          in_block_comment = false;
          at = end + 2;
        } else {
          const auto slash = line.find("//", at), block = line.find("/*", at);
          if (slash != std::string::npos && (block == std::string::npos || slash < block)) {
            part += line.substr(slash + 2);
            break;
          }
          if (block == std::string::npos) break;
          in_block_comment = true;
          at = block + 2;
        }
      }
    } else {
      part = line;
    }
    // Comment leaders and indentation are not words.
    static const std::regex kLeader(R"re(^\s*(///?|#+(?=\s)|\*|<!--|-->)?\s*)re");
    part = std::regex_replace(part, kLeader, "", std::regex_constants::format_first_only);
    if (part.empty()) continue;
    prose.line_starts.emplace_back(prose.text.size(), number);
    prose.text += part + " ";
  }
  return prose;
}

// What docs/ defines: the headings of each page and the tags written in bold.
struct DocsIndex {
  fs::path root;                                             // the repository
  std::map<std::string, std::vector<std::string>> headings;  // "docs/fba.md" -> heading texts
  std::map<std::string, int> bold_tags;                      // "V12" -> how many definitions
};

DocsIndex index_docs(const fs::path& root) {
  DocsIndex index;
  index.root = root;
  static const std::regex kHeading(R"re(^#+\s+(.*\S)\s*$)re");
  static const std::regex kBold(R"re(\*\*([^*]+)\*\*)re");
  for (const auto& entry : fs::directory_iterator(root / "docs")) {
    if (entry.path().extension() != ".md") continue;
    const std::string name = "docs/" + entry.path().filename().string();
    std::istringstream lines(test::read_text(entry.path().string()));
    std::string line;
    bool in_code = false;
    while (std::getline(lines, line)) {
      if (line.starts_with("```")) in_code = !in_code;
      std::smatch m;
      if (!in_code && std::regex_match(line, m, kHeading)) index.headings[name].push_back(m[1]);
      for (std::sregex_iterator it(line.begin(), line.end(), kBold), end; it != end; ++it) ++index.bold_tags[(*it)[1]];
    }
  }
  return index;
}

struct Finding {
  std::string file;
  int line;
  std::string what;
};

std::string describe(const std::vector<Finding>& findings) {
  std::string out;
  for (const Finding& f : findings) out += f.file + ":" + std::to_string(f.line) + ": " + f.what + "\n";
  return out;
}

// The repository path a cited page name stands for, or "" when it names nothing there. A bare
// name is looked for beside the citing file, at the top, and in docs/.
std::string resolve_page(const DocsIndex& docs, const std::string& citing, const std::string& name) {
  const fs::path beside = fs::path(citing).parent_path() / name;
  for (const fs::path& candidate : {fs::path(name), beside, fs::path("docs") / name}) {
    const std::string inside = candidate.lexically_normal().generic_string();
    if (inside.starts_with("..")) continue;  // outside the repository, even if it exists
    if (fs::is_regular_file(docs.root / inside)) return inside;
  }
  return "";
}

// Section numbers in "5.4 to 5.7, 6.7 and 6.8": every number given, ranges by their ends.
std::vector<std::string> section_numbers(const std::string& list) {
  static const std::regex kNumber(R"re([0-9]+(?:\.[0-9]+)*|[A-Z]\b)re");
  std::vector<std::string> numbers;
  for (std::sregex_iterator it(list.begin(), list.end(), kNumber), end; it != end; ++it) numbers.push_back((*it)[0]);
  return numbers;
}

bool has_section(const DocsIndex& docs, const std::string& page, const std::string& number) {
  const auto found = docs.headings.find(page);
  if (found == docs.headings.end()) return false;
  for (const std::string& heading : found->second) {
    if (number.size() == 1 && std::isupper(static_cast<unsigned char>(number[0]))) {
      if (heading.starts_with("Appendix " + number)) return true;
    } else if (heading.starts_with(number + ".") || heading.starts_with(number + " ")) {
      return true;
    }
  }
  return false;
}

bool has_heading(const DocsIndex& docs, const std::string& page, const std::string& title) {
  const auto found = docs.headings.find(page);
  if (found == docs.headings.end()) return false;
  static const std::regex kNumbering(R"re(^[0-9.A-Z-]*[0-9.]\s+)re");
  for (const std::string& heading : found->second) {
    const std::string bare = std::regex_replace(heading, kNumbering, "");
    if (bare.starts_with(title) || heading.starts_with(title)) return true;
  }
  return false;
}

// Every problem in one file. `path` is relative to the repository; `data` files (inputs under a
// corpus folder) are only checked for documents outside the repository.
std::vector<Finding> check_file(const DocsIndex& docs, const std::string& path, const std::string& content, bool data) {
  std::vector<Finding> findings;
  const Prose prose = prose_of(path, content);
  const std::string& text = prose.text;
  auto report = [&](std::size_t offset, std::string what) {
    findings.push_back({path, prose.line_at(offset), std::move(what)});
  };

  // 1. Documents that are not in the repository, by path or by the names they went under.
  static const std::regex kOutside(
      R"re((\.\./shared|\bshared/(docs|seeds|corpus)|\bseeds/[a-z]|\b(reference|bitstream|XMT-Omega|XMT/MP4) notes\b|\bnotes on (XMT|FBA|MP4)|\bproject brief\b|\bproject contract\b|\bshared docs\b|\bshared [A-Za-z0-9_-]+\.md|\b(format|shared) notes\b))re",
      std::regex::icase);
  for (std::sregex_iterator it(text.begin(), text.end(), kOutside), end; it != end; ++it)
    report(it->position(), "cites a document outside the repository: '" + (*it)[0].str() + "'");

  // Pages by name (x.md), then the sections cited in them.
  static const std::regex kPage(R"re(([A-Za-z0-9_./-]*[A-Za-z0-9_-]\.md)\b`?)re");
  static const std::regex kSectionAfterPage(
      R"re(^,?\s*(?:(?:(?:§){1,2}\s*|[Ss]ections?\s+|[Aa]ppendix\s+)((?:[0-9]+(?:\.[0-9]+)*|[A-Z]\b)(?:(?:\s*,\s*|\s+and\s+|\s+to\s+|\s*-\s*)(?:[0-9]+(?:\.[0-9]+)*))*)|\s*(?:\(|)"([^"]{3,60})"))re");
  std::vector<std::pair<std::size_t, std::string>> pages_cited;  // offset, page
  for (std::sregex_iterator it(text.begin(), text.end(), kPage), end; it != end; ++it) {
    const std::string name = (*it)[1];
    const std::string page = resolve_page(docs, path, name);
    if (page.empty()) {
      report(it->position(), "cites '" + name + "', which is not in the repository");
      continue;
    }
    pages_cited.emplace_back(it->position(), page);
    if (data) continue;
    const std::string after = text.substr(it->position() + it->length(), 120);
    std::smatch m;
    if (!std::regex_search(after, m, kSectionAfterPage)) continue;
    if (m[1].matched) {
      for (const std::string& number : section_numbers(m[1]))
        if (!has_section(docs, page, number)) report(it->position(), page + " has no section " + number);
    } else if (!has_heading(docs, page, m[2])) {
      report(it->position(), page + " has no heading \"" + m[2].str() + "\"");
    }
  }
  if (data) return findings;

  // Sections cited without a page: in a doc its own, in a source the page it cited last. Section
  // numbers of ISO/IEC standards ("14496-1 §7.2.6") are not the repository's.
  static const std::regex kBareSection(
      R"re(([0-9]{4,5}-[0-9]+\s*)?(?:(?:§){1,2}\s*|\b[Ss]ections?\s+)((?:[0-9]+(?:\.[0-9]+)*)(?:(?:\s*,\s*|\s+and\s+|\s+to\s+)(?:[0-9]+(?:\.[0-9]+)*))*))re");
  for (std::sregex_iterator it(text.begin(), text.end(), kBareSection), end; it != end; ++it) {
    if ((*it)[1].matched) continue;
    const std::size_t at = it->position();
    // "14496-1 §7.2.6 and §7.2.2.3", "XML 1.0 §2.4": sections of a standard named just before.
    const std::string lead = text.substr(at >= 40 ? at - 40 : 0, at >= 40 ? 40 : at);
    static const std::regex kStandard(
        R"re(\b(ISO|IEC|14496-[0-9]+|XML [0-9.]+|RFC [0-9]+|SMIL [0-9.]+|H\.26[0-9])\b)re");
    if (std::regex_search(lead, kStandard)) continue;
    // Already checked when it follows a page name directly.
    const std::string before = text.substr(at >= 6 ? at - 6 : 0, at >= 6 ? 6 : at);
    if (before.find(".md") != std::string::npos) continue;
    std::string page;
    if (path.starts_with("docs/") && path.ends_with(".md")) {
      page = path;
    } else {
      for (const auto& [offset, cited] : pages_cited)
        if (offset < at && cited.starts_with("docs/")) page = cited;
    }
    if (page.empty()) {
      report(at, "'" + (*it)[0].str() + "' of which document? Name the docs/ page before it");
      continue;
    }
    for (const std::string& number : section_numbers((*it)[2]))
      if (!has_section(docs, page, number)) report(at, page + " (cited above) has no section " + number);
  }

  // 2. Tags: each must be defined once in docs/, in bold, where a grep finds it.
  static const std::regex kTag(R"re(\b([VDE][0-9]{1,2}|Example [A-Z])\b)re");
  for (std::sregex_iterator it(text.begin(), text.end(), kTag), end; it != end; ++it) {
    const std::string tag = (*it)[1];
    const auto found = docs.bold_tags.find(tag);
    const int definitions = found == docs.bold_tags.end() ? 0 : found->second;
    if (definitions != 1)
      report(it->position(), "tag " + tag + " is defined " + std::to_string(definitions) + " times in docs/ (as **" +
                                 tag + "**); it must be defined once");
  }

  // 3. Tables, figures and definitions of the papers: say whose ("Mimic Table 1", "FML Figure 5",
  //    "Algebra definition 4"), and each must be described in docs/.
  static const std::regex kItem(
      R"re(\b(Tables?|Figures?|Figs?\.|[Dd]efinitions?)\s+([0-9]+(?:(?:\s*,\s*|\s+and\s+|\s+to\s+|\s*-\s*)[0-9]+)*))re");
  static const std::regex kPaperBefore(R"re((Mimic|FML|Algebra)\s+$)re");
  for (std::sregex_iterator it(text.begin(), text.end(), kItem), end; it != end; ++it) {
    const std::size_t at = it->position();
    const std::string before = text.substr(at >= 12 ? at - 12 : 0, at >= 12 ? 12 : at);
    std::smatch paper;
    if (!std::regex_search(before, paper, kPaperBefore)) {
      report(at, "'" + (*it)[0].str() + "' of which paper? Write 'Mimic " + (*it)[1].str() +
                     "', 'FML ...' or 'Algebra ...'");
      continue;
    }
    std::string kind = (*it)[1];
    if (kind.starts_with("Fig")) kind = "Figure";
    if (kind.starts_with("Table")) kind = "Table";
    if (kind.starts_with("Def") || kind.starts_with("def")) kind = "definition";
    const std::string list = (*it)[2];
    std::vector<int> numbers;
    static const std::regex kNumber(R"re([0-9]+)re");
    for (std::sregex_iterator n(list.begin(), list.end(), kNumber), nend; n != nend; ++n)
      numbers.push_back(std::stoi((*n)[0]));
    const bool range = list.find("to") != std::string::npos || list.find('-') != std::string::npos;
    if (range && numbers.size() == 2) {
      const int first = numbers[0], last = numbers[1];
      numbers.clear();
      for (int n = first; n <= last && n - first < 50; ++n) numbers.push_back(n);
    }
    for (int n : numbers) {
      const std::string tag = paper[1].str() + " " + kind + " " + std::to_string(n);
      const auto found = docs.bold_tags.find(tag);
      if (found == docs.bold_tags.end() || found->second != 1)
        report(at, "'" + tag + "' must be described once in docs/ (as **" + tag + "**)");
    }
  }
  return findings;
}

// The files a reader of the code reads: sources, build scripts, tests and docs, and the inputs
// under corpus folders (whose comments must not send readers outside either).
std::vector<std::pair<std::string, bool>> files_to_check(const fs::path& root) {
  static const std::set<std::string> kText = {".cpp",  ".hpp", ".h",   ".cmake", ".md",
                                              ".test", ".txt", ".xsd", ".in",    ".dict"};
  static const std::set<std::string> kData = {".md", ".xmt", ".fml", ".mimic", ".xpr", ".combine", ".profile"};
  std::vector<std::pair<std::string, bool>> files;  // path relative to root, data?
  for (const char* top : {"fapcodec", "transcoder", "xmt", "tools", "tests", "bench", "cmake", "docs", "corpus"}) {
    if (!fs::is_directory(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (!entry.is_regular_file()) continue;
      const std::string relative = fs::relative(entry.path(), root).generic_string();
      const std::string ext = entry.path().extension().string();
      // Inputs under corpus folders are data; their READMEs are docs like any other.
      const bool data = (relative.starts_with("corpus/") || relative.find("/corpus/") != std::string::npos) &&
                        entry.path().filename() != "README.md";
      if (relative == "tests/docs/doc_references_test.cpp") continue;  // quotes what it looks for
      if (data ? kData.count(ext) != 0 : kText.count(ext) != 0) files.emplace_back(relative, data);
    }
  }
  for (const char* top : {"README.md", "CMakeLists.txt"})
    if (fs::is_regular_file(root / top)) files.emplace_back(top, false);
  std::sort(files.begin(), files.end());
  return files;
}

const DocsIndex& DocReferences_docs() {
  static const DocsIndex index = index_docs(test::source_dir());
  return index;
}

class DocReferences : public ::testing::Test {
 protected:
  static const DocsIndex& docs() { return DocReferences_docs(); }
};

TEST_F(DocReferences, EverySourceAndDocCitesOnlyWhatTheRepositoryHolds) {
  const fs::path root = test::source_dir();
  std::vector<Finding> findings;
  std::size_t checked = 0;
  for (const auto& [path, data] : files_to_check(root)) {
    const auto found = check_file(docs(), path, test::read_text((root / path).string()), data);
    findings.insert(findings.end(), found.begin(), found.end());
    ++checked;
  }
  EXPECT_GT(checked, 300u);  // the walk found the tree
  EXPECT_TRUE(findings.empty()) << findings.size() << " citations a reader cannot follow:\n" << describe(findings);
}

TEST_F(DocReferences, TheTagsTheCodeUsesAreDefined) {
  // A sample of tags the sources rely on, looked up directly, so that an index that lost them
  // (a changed bold style, a renamed page) fails here by name.
  for (const char* tag : {"V1", "V8", "V12", "V17", "D4", "D6", "D7", "D8", "D9", "E9", "Mimic Table 1",
                          "Mimic Figure 1", "FML Figure 5", "Algebra definition 5"})
    EXPECT_EQ(docs().bold_tags.count(tag), 1u) << tag;
}

// The checker itself, on lines that must fail and lines that must pass: each case is a source
// text and the number of findings it must give.
struct Case {
  std::string text;
  std::size_t findings;
};

void expect_findings(const std::vector<Case>& cases) {
  for (const Case& c : cases)
    EXPECT_EQ(check_file(DocReferences_docs(), "x.cpp", c.text, false).size(), c.findings) << c.text;
}

TEST_F(DocReferences, FlagsCitationsOfOutsideDocuments) {
  // Built from pieces, so that this file does not cite what it tests for.
  const std::string shared = std::string("../") + "shared/docs/semantics.md";
  expect_findings({
      {"// See " + shared + " for the rules.\n", 2},  // the path and the page
      {"// Frame rates (" + std::string("fba-") + "bitstream.md section 5.3).\n", 0},
      {std::string("// As in the project's reference ") + "notes.\n", 1},
      {"// Blending (semantics" + std::string(".md §1).\n"), 1},
      {"// From each reader (shared " + std::string("fap-files.md section 3).\n"), 1},
      {"int code = 0;  // no citation here\n", 0},
  });
}

TEST_F(DocReferences, FlagsSectionsThatDoNotExist) {
  expect_findings({
      {"// The rewind (docs/fba-bitstream.md section 6.6).\n", 0},
      {"// The rewind (docs/fba-bitstream.md section 66.6).\n", 1},
      {"// docs/fba-bitstream.md sections 5.4 to 5.7, and\n// section 99 below.\n", 1},
      {"// The writer (docs/fap-files.md, \"Writing\").\n", 0},
      {"// The writer (docs/fap-files.md, \"Scribbling\").\n", 1},
      {"// Unanchored (section 4).\n", 1},
      {"// Descriptor tags (14496-1 §7.2.2.1).\n", 0},
      {"// Attribute values (XML 1.0 §2.4 and §3.3.3).\n", 0},
  });
}

TEST_F(DocReferences, FlagsTagsWithoutDefinition) {
  expect_findings({
      {"bool crlf = false;  // V1\n", 0},
      {"bool odd = false;  // V99\n", 1},
      {"// the reference skips a byte (D8), or\n// does not (D77)\n", 1},
      {"const char* hex = \"D77\";  // a string, not a comment\n", 0},
      {"// Example Q of somewhere\n", 1},
  });
}

TEST_F(DocReferences, FlagsPaperItemsWithoutThePaper) {
  expect_findings({
      {"// The grammar of Mimic Table 1.\n", 0},
      {"// The grammar of Table 1.\n", 1},
      {"// As in the Mimic\n// Figure 1 plot.\n", 0},
      {"// FML Figures 5 to 8.\n", 0},
      {"// Mimic Figure 99.\n", 1},
      {"// Algebra definitions 4 and 6.\n", 0},
  });
}

}  // namespace
}  // namespace fapc

// The row is the only place that knows a format (docs/architecture.md): no source of the pipeline
// or the program outside the table's entries (tools/pipeline/src/formats/, the list in
// registry.cpp) spells a kind name or an extension of the table as a string literal. A capability
// a new format needs is a field of its row, and a list of kinds in a message or the help is made
// from the table. The names checked are the table's own, so a new format is covered when it is
// added. The few literals that name something else (a subcommand, an option, a command's
// documented default) are listed below with their reason; any other fails this test.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "fapc/pipeline/registry.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

struct Literal {
  int line;
  std::string text;
};

// The string literals of C++ source `text` outside comments (ordinary and raw strings).
std::vector<Literal> string_literals(const std::string& text) {
  std::vector<Literal> found;
  int line = 1;
  const auto skip_to = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to && k < text.size(); ++k) line += text[k] == '\n' ? 1 : 0;
    return to;
  };
  for (std::size_t i = 0; i < text.size();) {
    if (text.compare(i, 2, "//") == 0) {
      i = skip_to(i, text.find('\n', i) == std::string::npos ? text.size() : text.find('\n', i));
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      i = skip_to(i, end == std::string::npos ? text.size() : end + 2);
    } else if (text[i] == '"' && i > 0 && text[i - 1] == 'R') {
      const std::size_t open = text.find('(', i);
      const std::string close = ")" + text.substr(i + 1, open - i - 1) + "\"";
      const std::size_t end = text.find(close, open);
      found.push_back({line, text.substr(open + 1, end - open - 1)});
      i = skip_to(i, end + close.size());
    } else if (text[i] == '"' || text[i] == '\'') {
      std::size_t j = i + 1;
      while (j < text.size() && text[j] != text[i]) j += text[j] == '\\' ? 2 : 1;
      if (text[i] == '"') found.push_back({line, text.substr(i + 1, j - i - 1)});
      i = skip_to(i, j + 1);
    } else {
      i = skip_to(i, i + 1);
    }
  }
  return found;
}

// Literals that spell a kind but name something else: (file under tools/, literal) -> how many.
const std::map<std::pair<std::string, std::string>, int> kOtherMeanings = {
    {{"fapc/cmd_combine.cpp", "combine"}, 6},  // the subcommand's name
    {{"fapc/cli_spec.cpp", "combine"}, 2},     // the subcommand and the option --states it takes
    {{"fapc/cli_spec.cpp", "json"}, 1},        // the option --json
    {{"fapc/cmd_faps.cpp", "json"}, 1},        // --json
    {{"fapc/cmd_verify.cpp", "json"}, 2},      // --json
    {{"fapc/cmd_formats.cpp", "json"}, 1},     // --json
    {{"fapc/cmd_info.cpp", "json"}, 2},        // --json
    {{"fapc/cmd_batch.cpp", "fap"}, 1},        // --to's documented default (docs/cli.md)
    {{"fapc/cmd_decode.cpp", "fap"}, 1},       // decode writes .fap text unless --to says otherwise
    {{"fapc/cmd_plot.cpp", "svg"}, 1},         // plot -o - writes SVG unless --to says otherwise
    {{"fapc/options.cpp", "arkit"}, 1},        // --morphs arkit: the 3D head's targets named by ARKit shape
};

bool is_table_file(const std::string& relative) {
  // The entries themselves, and `fapc plot`'s own writers, whose kinds are the plot's (PlotKind).
  return relative.starts_with("pipeline/src/formats/") || relative == "pipeline/src/registry.cpp" ||
         relative.starts_with("pipeline/src/plot/");
}

TEST(OnePlacePerFormat, TheScanFindsLiteralsOutsideComments) {
  const auto found = string_literals("a = \"fap\"; // \"fba\"\n/* \"mp4\" */ b(R\"x(.xmt)x\", 'q', \"a\\\"b\");");
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].text, "fap");
  EXPECT_EQ(found[1].text, ".xmt");
  EXPECT_EQ(found[1].line, 2);
  EXPECT_EQ(found[2].text, "a\\\"b");
}

TEST(OnePlacePerFormat, NoSourceOutsideTheTableSpellsAKindOrAnExtension) {
  std::set<std::string> names;
  for (const auto& f : pipeline::formats().inputs()) {
    names.insert(f.kind);
    names.insert(f.extensions.begin(), f.extensions.end());
  }
  for (const auto& f : pipeline::formats().outputs()) {
    names.insert(f.kind);
    names.insert(f.extensions.begin(), f.extensions.end());
  }
  const std::string tools = test::source_dir() + "/tools/";
  std::map<std::pair<std::string, std::string>, int> seen;
  std::string unexpected;
  for (const char* suffix : {".cpp", ".hpp"})
    for (const std::string& file : test::files_under(tools, suffix)) {
      const std::string relative = file.substr(tools.size());
      if (is_table_file(relative)) continue;
      for (const Literal& literal : string_literals(test::read_text(file))) {
        if (!names.contains(literal.text)) continue;
        const auto key = std::make_pair(relative, literal.text);
        const auto allowed = kOtherMeanings.find(key);
        if (allowed == kOtherMeanings.end() || ++seen[key] > allowed->second)
          unexpected += "tools/" + relative + ":" + std::to_string(literal.line) + ": \"" + literal.text + "\"\n";
      }
    }
  EXPECT_TRUE(unexpected.empty()) << "kind names or extensions outside the reader/writer table (make the "
                                     "capability a field of the row, or the list from the table):\n"
                                  << unexpected;
}

// The readers (xmt/, Mimic and the Algebra in transcoder/) and the timeline model name no format by
// its extension either (the writers' own libraries, face/ and the like, name what they write): a reader
// handed another reader's document names it from ReaderOptions::other_readers, made from the
// table's rows. An extension counts when a literal holds it as a word (".bml", "read it as .smil").
// Allowed: (file under the source tree, extension) -> why.
const std::map<std::pair<std::string, std::string>, std::string> kLibraryExtensions = {
    {{"xmt/bml/src/bml/recorded_speech.cpp", ".wav"}, "a BML speech's recorded audio named without extension"},
    {{"xmt/xmto/src/xmto/xmto_reader.cpp", ".xmt"}, "the XMT-Omega reader telling XMT-A from its own .xmt"},
};

bool holds_as_word(const std::string& literal, const std::string& extension) {
  for (std::size_t at = literal.find(extension); at != std::string::npos; at = literal.find(extension, at + 1)) {
    const std::size_t end = at + extension.size();
    const bool starts = at == 0 || literal[at - 1] == ' ' || literal[at - 1] == '(';
    const bool ends = end == literal.size() || std::string(" ),;:").find(literal[end]) != std::string::npos;
    if (starts && ends) return true;
  }
  return false;
}

TEST(OnePlacePerFormat, AWordScanFindsAnExtensionInAMessage) {
  EXPECT_TRUE(holds_as_word("(read it as .smil)", ".smil"));
  EXPECT_TRUE(holds_as_word(".bml", ".bml"));
  EXPECT_FALSE(holds_as_word("a.bml", ".bml"));
  EXPECT_FALSE(holds_as_word(".bmlseq", ".bml"));
}

TEST(OnePlacePerFormat, NoReaderNamesAnExtensionOfTheTable) {
  std::set<std::string> extensions;
  for (const auto& f : pipeline::formats().inputs()) extensions.insert(f.extensions.begin(), f.extensions.end());
  for (const auto& f : pipeline::formats().outputs()) extensions.insert(f.extensions.begin(), f.extensions.end());
  const std::string root = test::source_dir() + "/";
  std::string unexpected;
  for (const char* folder : {"xmt/", "transcoder/timeline/", "transcoder/src/", "transcoder/include/"})
    for (const char* suffix : {".cpp", ".hpp"})
      for (const std::string& file : test::files_under(root + folder, suffix)) {
        const std::string relative = file.substr(root.size());
        for (const Literal& literal : string_literals(test::read_text(file)))
          for (const std::string& extension : extensions)
            if (holds_as_word(literal.text, extension) && !kLibraryExtensions.contains({relative, extension}))
              unexpected += relative + ":" + std::to_string(literal.line) + ": \"" + literal.text + "\"\n";
      }
  EXPECT_TRUE(unexpected.empty()) << "a reader names a format of the table by its extension (take it from "
                                     "ReaderOptions::other_readers, made from the rows):\n"
                                  << unexpected;
}

}  // namespace
}  // namespace fapc

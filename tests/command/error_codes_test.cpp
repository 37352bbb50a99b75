// The tables of diagnostic codes (fapc/<library>/codes.def, tools/fapc/cli_codes.def): docs/errors.md
// lists them (FAPC_REGENERATE_GOLDEN=1 rewrites the list), every code is unique and well formed,
// and no source makes a code outside a table.
#include <gtest/gtest.h>

#include <map>
#include <regex>

#include "fapc/cli_codes.hpp"
#include "fapc/pipeline/code_tables.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

constexpr const char* kBegin = "<!-- code tables: begin -->\n";
constexpr const char* kEnd = "<!-- code tables: end -->\n";

std::vector<pipeline::CodeTable> all_tables() {
  std::vector<pipeline::CodeTable> tables = pipeline::code_tables();
  tables.push_back({"fapc (the command line)", codes::cli_codes});
  return tables;
}

// A table cell: '|' would end the cell.
std::string cell(const std::string& text) { return std::regex_replace(text, std::regex("\\|"), "\\|"); }

std::string listing() {
  std::string out;
  for (const pipeline::CodeTable& table : all_tables()) {
    out += "\n### " + std::string(table.library) +
           "\n\n| code | | kind | what it means, what to do |\n|---|---|---|---|\n";
    for (const CodeRow& row : table.rows) {
      const bool error = row.severity == Severity::error;
      out += "| `" + std::string(row.name) + "` | " + (error ? "error" : "warning") + " | " +
             (error ? std::string("`") + error_kind_name(row.kind) + "`" : "") + " | " + cell(row.meaning) + " |\n";
    }
  }
  return out;
}

TEST(ErrorCodes, DocsListEveryCode) {
  test::expect_generated_region("docs/errors.md", kBegin, kEnd, listing(), "the code tables (codes.def)");
}

TEST(ErrorCodes, EveryCodeIsUniqueAndWellFormed) {
  const std::regex form("[a-z0-9_]+\\.[a-z0-9_]+");
  std::map<std::string, std::string> seen;  // code -> library
  std::size_t errors = 0;
  for (const pipeline::CodeTable& table : all_tables()) {
    EXPECT_FALSE(table.rows.empty()) << table.library;
    for (const CodeRow& row : table.rows) {
      EXPECT_TRUE(std::regex_match(row.name, form)) << row.name << " is not a dotted lower-case name";
      const auto [at, fresh] = seen.emplace(row.name, table.library);
      EXPECT_TRUE(fresh) << row.name << " is in the tables of " << at->second << " and " << table.library;
      EXPECT_GT(std::string(row.meaning).size(), 10u) << row.name << " says nothing of what it means";
      errors += row.severity == Severity::error;
    }
  }
  EXPECT_GT(errors, 150u);
}

const std::regex& made_outside_a_table() {
  static const std::regex made(
      R"((ErrorCode|WarningCode)\s*\{\s*"|make_warning\(\s*\{|\.code = "|Diagnostic\{\s*Severity::error|make_diagnostic\(\s*Severity::error)");
  return made;
}

TEST(ErrorCodes, TheScanFindsTheShapesItLooksFor) {
  for (const std::string line : {"make_warning({\"fap.value\"}, at, m)", "WarningCode{\"bml.x\"}",
                                 "ErrorCode{ \"a.b\", k}", "w.code = \"bml.x\";", "Diagnostic{Severity::error, at, m}"})
    EXPECT_TRUE(std::regex_search(line, made_outside_a_table())) << line;
  for (const std::string line :
       {"make_warning(codes::fap::value, at, m)", "make_error(codes::io::cannot_open, at, m)", "d.code = code.name;"})
    EXPECT_FALSE(std::regex_search(line, made_outside_a_table())) << line;
}

// A code is only ever declared in a table: ErrorCode{...} or WarningCode{...}, a braced name passed
// to make_warning or a name assigned to a diagnostic's code anywhere else would be a code that
// docs/errors.md does not list; and an error is only made by make_error, which takes a code.
TEST(ErrorCodes, NoSourceMakesACodeOutsideATable) {
  std::vector<std::string> offenders;
  for (const std::string folder : {"fapcodec", "transcoder", "xmt", "tools"})
    for (const std::string suffix : {".cpp", ".hpp"})
      for (const std::string& file : test::files_under(test::source_dir() + "/" + folder, suffix)) {
        if (file.ends_with("/fapc/codec/diagnostic.hpp")) continue;  // make_error itself
        if (std::regex_search(test::read_text(file), made_outside_a_table())) offenders.push_back(file);
      }
  EXPECT_TRUE(offenders.empty()) << "codes made outside a codes.def table in: " << ::testing::PrintToString(offenders);
}

}  // namespace
}  // namespace fapc

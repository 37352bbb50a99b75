// A mapping of outside vocabulary (FACS action units, ARKit blendshapes) onto MPEG-4 FAPs, read
// from fapc's own tab-separated tables (transcoder/vocabulary/data/, docs/bridges.md). The tables
// are compiled in; a user's replacement file is read by the same parser, with the same positioned
// errors.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::vocabulary {

// What a table's first column names, which decides how a key is checked.
enum class TableKind {
  action_units,  // column `au`: a FACS action unit number, 1-99
  arkit_shapes,  // column `shape`: one of ARKit's 52 blendshape names (arkit_shapes.hpp)
};

struct MappingRow {
  std::string key;     // "12", "mouthSmileLeft"
  int fap = 0;         // 3..68; 0 when no FAP carries the key (the row then names the loss)
  double amount = 0;   // the FAP's value, in its FAP units, at the key's full intensity or weight
  std::string reason;  // why the row holds
  int line = 0;        // where the row is in its file
};

struct MappingTable {
  TableKind kind = TableKind::action_units;
  std::string source;            // the file it was read from ("au_faps.tsv" for the bundled one)
  std::vector<MappingRow> rows;  // in file order

  // The rows of one key (those with fap 0 included), in file order.
  std::vector<MappingRow> rows_of(std::string_view key) const;
  bool has_key(std::string_view key) const;
  // Keys in order of first appearance.
  std::vector<std::string> keys() const;
  // True when the key has rows but none carries a FAP (AU 57: a head translation).
  bool is_lost(std::string_view key) const;
};

// A table of more rows than this is refused before it is stored (docs/bridges.md).
inline constexpr std::size_t kMaxTableRows = 10000;

// Reads a table. Lines starting with '#' and empty lines are skipped; the first other line is the
// header (`au` or `shape`, then `fap direction amount reason`), separated by tabs. Every error
// points at its line and column: unknown FAP names and keys (with the closest names), a direction
// that disagrees with the sign, an amount outside the FAP's legal range, a key and FAP given twice,
// a key with both `-` and FAP rows, and (for ARKit) a shape without any row.
Result<MappingTable> parse_mapping_table(std::string_view text, const std::string& file, TableKind kind);

// The bundled tables, parsed once.
const MappingTable& action_unit_table();
const MappingTable& arkit_table();

// The bundled files' text by name ("au_faps.tsv", "arkit_faps.tsv", "visemes.tsv"); empty when no
// such file is bundled.
std::string_view bundled_table_text(std::string_view name);

// The data rows of a bundled table (header, comments and empty lines dropped), each split at its
// tabs: for tables of fapc's own whose rows are checked by their tests, not by a parser.
std::vector<std::vector<std::string_view>> bundled_table_cells(std::string_view name);

}  // namespace fapc::vocabulary

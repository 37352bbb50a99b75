#include "fapc/vocabulary/mapping_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "fapc/codec/did_you_mean.hpp"
#include "fapc/codec/fap_table.hpp"
#include "fapc/vocabulary/arkit_shapes.hpp"
#include "fapc/vocabulary/codes.hpp"
#include "tsv_lines.hpp"

namespace fapc::vocabulary {
namespace {

// The word for the way a FAP's feature point moves when its value is negative.
std::string_view opposite(std::string_view positive) {
  static const std::pair<std::string_view, std::string_view> pairs[] = {{"up", "down"},
                                                                        {"left", "right"},
                                                                        {"forward", "backward"},
                                                                        {"growing", "shrinking"},
                                                                        {"concave upward", "concave downward"}};
  for (const auto& [a, b] : pairs) {
    if (positive == a) return b;
    if (positive == b) return a;
  }
  return {};
}

std::vector<std::string> arkit_candidates() {
  std::vector<std::string> names;
  for (std::string_view name : arkit_shape_names()) names.emplace_back(name);
  return names;
}

// The key as the table stores it ("12", "mouthSmileLeft"), or an error at its cell.
Result<std::string> check_key(const std::string& file, const TsvLine& line, const TsvCell& cell, TableKind kind) {
  if (kind == TableKind::action_units) {
    int au = 0;
    const char* end = cell.text.data() + cell.text.size();
    const auto [ptr, ec] = std::from_chars(cell.text.data(), end, au);
    if (ec != std::errc{} || ptr != end || au < 1 || au > 99) {
      return cell_error(codes::vocabulary::bad_value, file, line, cell,
                        "'" + std::string(cell.text) + "' is not an action unit number (1-99)");
    }
    return std::to_string(au);
  }
  const std::optional<int> shape = find_arkit_shape(cell.text);
  if (!shape || arkit_shape_names()[static_cast<std::size_t>(*shape)] != cell.text) {
    return cell_error(codes::vocabulary::unknown_name, file, line, cell,
                      "'" + std::string(cell.text) + "' is not one of ARKit's 52 shape names (camelCase)" +
                          did_you_mean(cell.text, arkit_candidates()));
  }
  return std::string(cell.text);
}

// One row's FAP, direction and amount, checked against the FAP table.
Status check_motion(const std::string& file, const TsvLine& line, MappingRow& row) {
  const TsvCell& fap_cell = line.cells[1];
  const TsvCell& direction_cell = line.cells[2];
  const TsvCell& amount_cell = line.cells[3];
  if (fap_cell.text == "-") {
    if (direction_cell.text != "-" || amount_cell.text != "0") {
      return cell_error(codes::vocabulary::bad_value, file, line, direction_cell,
                        "a row without a FAP ('-') has direction '-' and amount 0");
    }
    return ok_status();
  }
  const FapInfo* info = find_fap_by_name_or_number(fap_cell.text);
  if (!info || info->number < 3) {
    return cell_error(codes::vocabulary::bad_value, file, line, fap_cell,
                      info
                          ? "FAP " + std::to_string(info->number) + " is high-level; a table row names one of FAPs 3-68"
                          : unknown_fap_message(fap_cell.text));
  }
  row.fap = info->number;
  const std::optional<double> amount = finite_number(amount_cell.text);
  if (!amount || *amount == 0) {
    return cell_error(codes::vocabulary::bad_value, file, line, amount_cell,
                      "'" + std::string(amount_cell.text) + "' is not a non-zero number");
  }
  if (std::abs(*amount) > info->legal_max()) {
    return cell_error(codes::vocabulary::bad_value, file, line, amount_cell,
                      std::string(amount_cell.text) + " is outside " + std::string(info->name) +
                          "'s legal range of +-" + std::to_string(info->legal_max()));
  }
  row.amount = *amount;
  const std::string_view expected = *amount > 0 ? info->positive_motion : opposite(info->positive_motion);
  if (direction_cell.text != expected) {
    return cell_error(codes::vocabulary::bad_value, file, line, direction_cell,
                      "direction '" + std::string(direction_cell.text) + "' disagrees with amount " +
                          std::string(amount_cell.text) + ": a " + (*amount > 0 ? "positive " : "negative ") +
                          std::string(info->name) + " moves " + std::string(expected));
  }
  return ok_status();
}

}  // namespace

std::vector<MappingRow> MappingTable::rows_of(std::string_view key) const {
  std::vector<MappingRow> out;
  for (const MappingRow& row : rows) {
    if (row.key == key) out.push_back(row);
  }
  return out;
}

bool MappingTable::has_key(std::string_view key) const {
  for (const MappingRow& row : rows) {
    if (row.key == key) return true;
  }
  return false;
}

std::vector<std::string> MappingTable::keys() const {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const MappingRow& row : rows) {
    if (seen.insert(row.key).second) out.push_back(row.key);
  }
  return out;
}

bool MappingTable::is_lost(std::string_view key) const {
  bool any = false;
  for (const MappingRow& row : rows) {
    if (row.key != key) continue;
    if (row.fap != 0) return false;
    any = true;
  }
  return any;
}

Result<MappingTable> parse_mapping_table(std::string_view text, const std::string& file, TableKind kind) {
  Result<std::vector<TsvLine>> lines = split_tsv(text, file, kMaxTableRows + 1);
  if (!lines) return lines.error();
  const std::string_view key_column = kind == TableKind::action_units ? "au" : "shape";
  if (Status columns = check_columns(*lines, file, {key_column, "fap", "direction", "amount", "reason"}); !columns) {
    return columns.error();
  }
  MappingTable table{kind, file, {}};
  table.rows.reserve(lines->size() - 1);
  std::map<std::pair<std::string, int>, int> seen;  // (key, fap) -> line
  std::set<std::string> keys_lost, keys_with_fap;
  for (std::size_t i = 1; i < lines->size(); ++i) {
    const TsvLine& line = (*lines)[i];
    Result<std::string> key = check_key(file, line, line.cells[0], kind);
    if (!key) return key.error();
    MappingRow row{*key, 0, 0, std::string(line.cells[4].text), line.line};
    if (Status motion = check_motion(file, line, row); !motion) return motion.error();
    if (row.reason.empty())
      return cell_error(codes::vocabulary::no_reason, file, line, line.cells[4],
                        "every row says why it holds: the reason is empty");
    const auto [it, fresh] = seen.emplace(std::make_pair(row.key, row.fap), line.line);
    if (!fresh) {
      return cell_error(codes::vocabulary::duplicate_row, file, line, line.cells[1],
                        "'" + row.key + "' and " + std::string(line.cells[1].text) + " are already given on line " +
                            std::to_string(it->second));
    }
    (row.fap == 0 ? keys_lost : keys_with_fap).insert(row.key);
    if (keys_lost.count(row.key) > 0 && keys_with_fap.count(row.key) > 0) {
      return cell_error(codes::vocabulary::duplicate_row, file, line, line.cells[1],
                        "'" + row.key + "' has both a row without a FAP ('-') and rows with FAPs");
    }
    table.rows.push_back(std::move(row));
  }
  if (kind == TableKind::arkit_shapes) {
    for (std::string_view shape : arkit_shape_names()) {
      if (!table.has_key(shape)) {
        return make_error(codes::vocabulary::missing_row, Location::text(file, lines->front().line, 1),
                          "shape '" + std::string(shape) +
                              "' has no row: every one of the 52 shapes needs one "
                              "(a row with fap '-' if no FAP carries it)",
                          std::string(lines->front().whole));
      }
    }
  }
  return table;
}

namespace {

MappingTable load_bundled(std::string_view name, TableKind kind) {
  // The bundled files are tested (tests/vocabulary), so a parse failure cannot reach a user; an
  // empty table keeps a broken build from crashing.
  Result<MappingTable> parsed = parse_mapping_table(bundled_table_text(name), std::string(name), kind);
  return parsed ? std::move(*parsed) : MappingTable{kind, std::string(name), {}};
}

}  // namespace

const MappingTable& action_unit_table() {
  static const MappingTable table = load_bundled("au_faps.tsv", TableKind::action_units);
  return table;
}

const MappingTable& arkit_table() {
  static const MappingTable table = load_bundled("arkit_faps.tsv", TableKind::arkit_shapes);
  return table;
}

}  // namespace fapc::vocabulary

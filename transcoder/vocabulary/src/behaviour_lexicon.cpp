#include "fapc/vocabulary/behaviour_lexicon.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <set>

#include "fapc/codec/did_you_mean.hpp"
#include "fapc/vocabulary/codes.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "tsv_lines.hpp"

namespace fapc::vocabulary {
namespace {

bool same_word(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](unsigned char x, unsigned char y) {
           return std::tolower(x) == std::tolower(y);
         });
}

// The faceLexeme names of bml_lexemes.tsv (its first column), which the BML reader draws.
std::vector<std::string> face_lexemes() {
  std::vector<std::string> out;
  const Result<std::vector<TsvLine>> lines =
      split_tsv(bundled_table_text("bml_lexemes.tsv"), "bml_lexemes.tsv", kMaxLexiconRows);
  if (!lines) return out;
  for (std::size_t i = 1; i < lines->size(); ++i) {
    const std::string name((*lines)[i].cells[0].text);
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  return out;
}

const std::vector<std::string>& head_lexemes() {
  static const std::vector<std::string> names = {"NOD", "SHAKE", "TILT", "TILT_LEFT", "TILT_RIGHT"};
  return names;
}

const std::vector<std::string>& directions() {
  static const std::vector<std::string> names = {"LEFT",   "RIGHT",   "UP",       "DOWN",
                                                 "UPLEFT", "UPRIGHT", "DOWNLEFT", "DOWNRIGHT"};
  return names;
}

Result<LexiconBehaviour> behaviour_of(const std::string& file, const TsvLine& line, const TsvCell& cell) {
  static const std::pair<std::string_view, LexiconBehaviour> kinds[] = {
      {"lexeme", LexiconBehaviour::lexeme},      {"au", LexiconBehaviour::unit},
      {"head", LexiconBehaviour::head},          {"gaze", LexiconBehaviour::gaze},
      {"headturn", LexiconBehaviour::head_turn}, {"none", LexiconBehaviour::none}};
  for (const auto& [name, kind] : kinds)
    if (cell.text == name) return kind;
  return cell_error(codes::vocabulary::unknown_name, file, line, cell,
                    "'" + std::string(cell.text) + "' is not a behaviour: lexeme, au, head, gaze, headturn or none" +
                        did_you_mean(cell.text, {"lexeme", "au", "head", "gaze", "headturn", "none"}));
}

// The name cell as the behaviour reads it.
Status check_name(const std::string& file, const TsvLine& line, const TsvCell& cell, LexiconRow& row) {
  const std::string name(cell.text);
  auto unknown = [&](const std::string& what, const std::vector<std::string>& known) {
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    return cell_error(codes::vocabulary::unknown_name, file, line, cell,
                      "'" + name + "' is not " + what + " (" + list + ")" + did_you_mean(name, known));
  };
  switch (row.behaviour) {
    case LexiconBehaviour::lexeme: {
      const std::vector<std::string> known = face_lexemes();
      if (std::find(known.begin(), known.end(), name) == known.end())
        return unknown("a face lexeme of bml_lexemes.tsv", known);
      break;
    }
    case LexiconBehaviour::unit: {
      std::string_view digits = cell.text;
      if (!digits.empty() && (digits[0] == 'L' || digits[0] == 'R')) {
        row.side = digits[0];
        digits.remove_prefix(1);
      }
      const char* end = digits.data() + digits.size();
      const auto [ptr, ec] = std::from_chars(digits.data(), end, row.unit);
      if (ec != std::errc{} || ptr != end || row.unit < 1 || row.unit > 99)
        return cell_error(codes::vocabulary::bad_value, file, line, cell,
                          "'" + name + "' is not an action unit: 1-99, L or R in front for one side");
      const MappingTable& units = action_unit_table();
      const std::string key = std::to_string(row.unit);
      if (!units.has_key(key) || units.is_lost(key))
        return cell_error(codes::vocabulary::draws_nothing, file, line, cell,
                          "action unit " + key + " moves no FAP in au_faps.tsv: it would draw nothing");
      break;
    }
    case LexiconBehaviour::head: {
      std::string lexeme = name;
      if (const std::size_t star = name.find('*'); star != std::string::npos) {
        lexeme = name.substr(0, star);
        const std::string_view count = std::string_view(name).substr(star + 1);
        const auto [ptr, ec] = std::from_chars(count.data(), count.data() + count.size(), row.repetition);
        if (ec != std::errc{} || ptr != count.data() + count.size() || row.repetition < 1 || row.repetition > 20)
          return cell_error(codes::vocabulary::bad_value, file, line, cell,
                            "'" + name + "': the repetitions after '*' are a whole number from 1 to 20");
      }
      const auto& known = head_lexemes();
      if (std::find(known.begin(), known.end(), lexeme) == known.end())
        return unknown("a head lexeme fapc draws", known);
      row.name = lexeme;
      return ok_status();
    }
    case LexiconBehaviour::gaze:
    case LexiconBehaviour::head_turn: {
      const auto& known = directions();
      if (std::find(known.begin(), known.end(), name) == known.end()) return unknown("a direction", known);
      break;
    }
    case LexiconBehaviour::none:
      if (name != "-")
        return cell_error(codes::vocabulary::bad_value, file, line, cell, "a `none` row names nothing: write '-'");
      break;
  }
  row.name = name;
  return ok_status();
}

}  // namespace

namespace {

// The rows of one lexicon alone: the value's, else the intention's "*" rows.
std::vector<const LexiconRow*> own_rows(const std::vector<LexiconRow>& rows, std::string_view intention,
                                        std::string_view value) {
  std::vector<const LexiconRow*> exact, any;
  for (const LexiconRow& row : rows) {
    if (!same_word(row.intention, intention)) continue;
    if (same_word(row.value, value))
      exact.push_back(&row);
    else if (row.value == "*")
      any.push_back(&row);
  }
  return exact.empty() ? any : exact;
}

}  // namespace

std::vector<const LexiconRow*> BehaviourLexicon::rows_for(std::string_view intention, std::string_view value) const {
  std::vector<const LexiconRow*> found = own_rows(rows, intention, value);
  if (found.empty() && same_word(intention, "affect")) found = own_rows(rows, "emotion", value);
  if (found.empty() && base != nullptr) found = base->rows_for(intention, value);
  return found;
}

bool BehaviourLexicon::knows(std::string_view intention) const {
  for (const LexiconRow& row : rows)
    if (same_word(row.intention, intention)) return true;
  if (same_word(intention, "affect") && knows("emotion")) return true;
  return base != nullptr && base->knows(intention);
}

Result<BehaviourLexicon> parse_behaviour_lexicon(std::string_view text, const std::string& file) {
  Result<std::vector<TsvLine>> lines = split_tsv(text, file, kMaxLexiconRows + 1);
  if (!lines) return lines.error();
  if (Status columns = check_columns(
          *lines, file,
          {"intention", "value", "behaviour", "name", "amount", "start", "ready", "relax", "end", "reason"});
      !columns)
    return columns.error();
  BehaviourLexicon lexicon{file, {}};
  lexicon.rows.reserve(lines->size() - 1);
  for (std::size_t i = 1; i < lines->size(); ++i) {
    const TsvLine& line = (*lines)[i];
    const auto& cells = line.cells;
    LexiconRow row;
    row.line = line.line;
    row.intention = std::string(cells[0].text);
    row.value = std::string(cells[1].text);
    if (row.intention.empty())
      return cell_error(codes::vocabulary::empty_cell, file, line, cells[0], "the intention is empty");
    if (row.value.empty())
      return cell_error(codes::vocabulary::empty_cell, file, line, cells[1],
                        "the value is empty: write '*' for every value");
    Result<LexiconBehaviour> behaviour = behaviour_of(file, line, cells[2]);
    if (!behaviour) return behaviour.error();
    row.behaviour = *behaviour;
    if (Status name = check_name(file, line, cells[3], row); !name) return name.error();
    const auto amount = finite_number(cells[4].text);
    if (!amount)
      return cell_error(codes::vocabulary::bad_value, file, line, cells[4],
                        "'" + std::string(cells[4].text) + "' is not a number");
    const double limit =
        row.behaviour == LexiconBehaviour::gaze || row.behaviour == LexiconBehaviour::head_turn ? 60 : 2;
    if (std::abs(*amount) > limit)
      return cell_error(codes::vocabulary::bad_value, file, line, cells[4],
                        "the amount " + std::string(cells[4].text) + " is beyond " +
                            (limit == 60 ? "60 degrees" : "twice the behaviour's full size"));
    row.amount = *amount;
    double* fractions[] = {&row.start, &row.ready, &row.relax, &row.end};
    double previous = 0;
    for (int f = 0; f < 4; ++f) {
      const TsvCell& cell = cells[5 + static_cast<std::size_t>(f)];
      const auto fraction = finite_number(cell.text);
      if (!fraction || *fraction < 0 || *fraction > 1)
        return cell_error(codes::vocabulary::bad_value, file, line, cell,
                          "'" + std::string(cell.text) + "' is not a fraction of the span (0 to 1)");
      if (*fraction < previous)
        return cell_error(codes::vocabulary::bad_value, file, line, cell,
                          "the fractions start, ready, relax, end must not decrease: " + std::string(cell.text) +
                              " comes after " + std::to_string(previous));
      *fractions[f] = previous = *fraction;
    }
    if (row.end <= row.start)
      return cell_error(codes::vocabulary::bad_value, file, line, cells[8], "the behaviour must end after it starts");
    row.reason = std::string(cells[9].text);
    if (row.reason.empty())
      return cell_error(codes::vocabulary::no_reason, file, line, cells[9],
                        "every row says why it holds: the reason is empty");
    lexicon.rows.push_back(std::move(row));
  }
  return lexicon;
}

const BehaviourLexicon& bundled_behaviour_lexicon() {
  // fapc's own file, checked by the vocabulary tests: a defect here is a build defect.
  static const BehaviourLexicon lexicon = [] {
    Result<BehaviourLexicon> parsed = parse_behaviour_lexicon(bundled_table_text("intentions.tsv"), "intentions.tsv");
    return parsed ? std::move(*parsed) : BehaviourLexicon{"intentions.tsv", {}};
  }();
  return lexicon;
}

const BehaviourLexicon& bundled_greta_references() {
  static const BehaviourLexicon lexicon = [] {
    Result<BehaviourLexicon> parsed =
        parse_behaviour_lexicon(bundled_table_text("greta_references.tsv"), "greta_references.tsv");
    return parsed ? std::move(*parsed) : BehaviourLexicon{"greta_references.tsv", {}};
  }();
  return lexicon;
}

}  // namespace fapc::vocabulary

#include "fml/speech_visemes.hpp"

#include <set>
#include <utility>

#include "fapc/fml/codes.hpp"
#include "fapc/xml/text.hpp"

namespace fapc::fml {
namespace {

// The letter groups of visemes_from_text, longest first where they overlap.
constexpr std::pair<std::string_view, int> kDigraphs[] = {{"th", 3}, {"sh", 6}, {"ch", 6}, {"ph", 2},
                                                          {"ng", 8}, {"ck", 5}, {"qu", 5}};

int viseme_of_letter(char c) {
  switch (c) {
    case 'p':
    case 'b':
    case 'm':
      return 1;
    case 'f':
    case 'v':
      return 2;
    case 't':
    case 'd':
      return 4;
    case 'k':
    case 'g':
    case 'c':
    case 'q':
    case 'x':
      return 5;
    case 'j':
      return 6;
    case 's':
    case 'z':
      return 7;
    case 'n':
    case 'l':
      return 8;
    case 'r':
      return 9;
    case 'a':
      return 10;
    case 'e':
      return 11;
    case 'i':
    case 'y':
      return 12;
    case 'o':
      return 13;
    case 'u':
    case 'w':
      return 14;
    default:
      return -1;
  }
}

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

bool is_pause(char c) { return c == '.' || c == ',' || c == ';' || c == ':' || c == '!' || c == '?'; }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Slots: a viseme number, or 0 for a silent slot.
std::vector<int> letter_slots(std::string_view text, std::string& skipped) {
  std::vector<int> slots;
  std::set<char> odd;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = lower(text[i]);
    if (is_space(c)) {
      while (i < text.size() && is_space(text[i])) ++i;
      slots.push_back(0);
      continue;
    }
    if (is_pause(c)) {
      slots.insert(slots.end(), {0, 0});
      ++i;
      continue;
    }
    bool digraph = false;
    for (const auto& [letters, viseme] : kDigraphs) {
      if (i + 1 < text.size() && c == letters[0] && lower(text[i + 1]) == letters[1]) {
        slots.push_back(viseme);
        i += 2;
        digraph = true;
        break;
      }
    }
    if (digraph) continue;
    const int viseme = viseme_of_letter(c);
    if (c == 'h' || c == '\'' || c == '-') {
      // No mouth shape of its own (h, and the apostrophe and hyphen inside words).
    } else if (viseme < 0) {
      odd.insert(text[i]);
      slots.push_back(0);
    } else if (!(i > 0 && lower(text[i - 1]) == c)) {  // a doubled letter is said once
      slots.push_back(viseme);
    }
    ++i;
  }
  // Silence at either end is not part of the utterance.
  while (!slots.empty() && slots.back() == 0) slots.pop_back();
  std::size_t first = 0;
  while (first < slots.size() && slots[first] == 0) ++first;
  slots.erase(slots.begin(), slots.begin() + static_cast<std::ptrdiff_t>(first));
  for (const char c : odd) skipped += c;
  return slots;
}

// Spans from consecutive slots of one length: equal neighbours merge into one span.
Speech speech_from_slots(const std::vector<int>& slots, double slot) {
  Speech speech;
  speech.duration = static_cast<double>(slots.size()) * slot;
  for (std::size_t k = 0; k < slots.size(); ++k) {
    if (slots[k] == 0) continue;
    const double begin = static_cast<double>(k) * slot;
    if (!speech.visemes.empty() && speech.visemes.back().viseme == slots[k] && speech.visemes.back().end == begin) {
      speech.visemes.back().end = begin + slot;
    } else {
      speech.visemes.push_back(VisemeSpan{slots[k], begin, begin + slot});
    }
  }
  return speech;
}

std::string_view next_field(std::string_view line, std::size_t& at) {
  while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
  const std::size_t start = at;
  while (at < line.size() && line[at] != ' ' && line[at] != '\t') ++at;
  return line.substr(start, at - start);
}

}  // namespace

int viseme_of_phoneme(std::string_view p) {
  // ISO/IEC 14496-2 Annex C: 1 p b m, 2 f v, 3 T D, 4 t d, 5 k g, 6 tS dZ S, 7 s z, 8 n l, 9 r,
  // 10 A:, 11 e, 12 I, 13 Q, 14 U. Other SAMPA phonemes go to the nearest of these shapes: long
  // and short variants together, diphthongs by their first vowel, Z with S, N with n, j with I,
  // w with U, h and the glottal stop silent (they have no mouth shape of their own).
  static const std::pair<std::string_view, int> kTable[] = {
      {"_", 0},   {"#", 0},   {"h", 0},   {"?", 0},   {"p", 1},   {"b", 1},   {"m", 1},   {"f", 2},   {"v", 2},
      {"T", 3},   {"D", 3},   {"t", 4},   {"d", 4},   {"k", 5},   {"g", 5},   {"x", 5},   {"tS", 6},  {"dZ", 6},
      {"S", 6},   {"Z", 6},   {"s", 7},   {"z", 7},   {"n", 8},   {"l", 8},   {"N", 8},   {"r", 9},   {"R", 9},
      {"A:", 10}, {"A", 10},  {"a", 10},  {"a:", 10}, {"V", 10},  {"aI", 10}, {"aU", 10}, {"e", 11},  {"e:", 11},
      {"E", 11},  {"E:", 11}, {"@", 11},  {"3:", 11}, {"{", 11},  {"eI", 11}, {"e@", 11}, {"I", 12},  {"i", 12},
      {"i:", 12}, {"j", 12},  {"I@", 12}, {"y", 12},  {"y:", 12}, {"Q", 13},  {"O", 13},  {"O:", 13}, {"o", 13},
      {"o:", 13}, {"OI", 13}, {"@U", 13}, {"U", 14},  {"u", 14},  {"u:", 14}, {"w", 14},  {"U@", 14},
  };
  for (const auto& [name, viseme] : kTable)
    if (name == p) return viseme;
  return -1;
}

Speech visemes_from_text(std::string_view text, double visemes_per_second, std::string& skipped) {
  return speech_from_slots(letter_slots(text, skipped), 1.0 / visemes_per_second);
}

Result<Speech> visemes_from_pho(std::string_view text, const std::string& file_name, Diagnostics& warnings) {
  Speech speech;
  std::set<std::string, std::less<>> unknown;
  int line_number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t stop = text.find('\n', start);
    if (stop == std::string_view::npos) stop = text.size();
    std::string_view line = text.substr(start, stop - start);
    ++line_number;
    start = stop + 1;
    if (const std::size_t comment = line.find(';'); comment != std::string_view::npos) line = line.substr(0, comment);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    std::size_t at = 0;
    const std::string_view phoneme = next_field(line, at);
    if (phoneme.empty()) continue;
    const auto column = [&](std::string_view field) { return static_cast<int>(field.data() - line.data()) + 1; };
    const std::string_view length = next_field(line, at);
    const std::optional<double> parsed = xml::decimal(length);
    const double ms = parsed.value_or(-1);
    if (!parsed || ms < 0 || ms > 60000) {
      const int col = length.empty() ? static_cast<int>(line.size()) + 1 : column(length);
      return make_error(codes::pho::bad_duration, Location::text(file_name, line_number, col),
                        "phoneme '" + std::string(phoneme) + "' needs a duration in milliseconds (0 to 60000)",
                        std::string(line));
    }
    // The pitch points (position %, Hz) are the voice's, not the face's: checked, then unused.
    for (std::string_view field = next_field(line, at); !field.empty(); field = next_field(line, at)) {
      if (!xml::decimal(field)) {
        return make_error(codes::pho::not_a_number, Location::text(file_name, line_number, column(field)),
                          "'" + std::string(field) + "' is not a number (pitch points are position% and Hz)",
                          std::string(line));
      }
    }
    const double begin = speech.duration;
    speech.duration += ms / 1000.0;
    int viseme = viseme_of_phoneme(phoneme);
    if (viseme < 0) {
      if (unknown.insert(std::string(phoneme)).second) {
        warnings.push_back(
            make_warning(codes::fml::phoneme_silence, Location::text(file_name, line_number, column(phoneme)),
                         "phoneme '" + std::string(phoneme) + "' has no MPEG-4 viseme and is treated as silence",
                         std::string(line)));
      }
      viseme = 0;
    }
    if (viseme == 0 || ms == 0) continue;
    if (!speech.visemes.empty() && speech.visemes.back().viseme == viseme && speech.visemes.back().end == begin) {
      speech.visemes.back().end = speech.duration;
    } else {
      speech.visemes.push_back(VisemeSpan{viseme, begin, speech.duration});
    }
  }
  return speech;
}

}  // namespace fapc::fml

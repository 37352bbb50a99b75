// The table of docs/speech.md. MPEG-4 visemes (ISO/IEC 14496-2, the table the .pho path uses):
// 1 PP p b m, 2 FF f v, 3 TH T D, 4 DD t d, 5 kk k g, 6 CH tS dZ S, 7 SS s z, 8 nn n l, 9 RR r,
// 10 AA A:, 11 E e, 12 ih I, 13 oh Q, 14 ou U. eSpeak NG names phonemes with ASCII mnemonics
// (close to Kirshenbaum's); every sound is placed at the viseme whose mouth shape it shares:
// vowels by openness and rounding (rounded front vowels with the rounded ones, since the lips are
// what shows), affricates by their release, syllabic consonants with the consonant.
#include <string>
#include <utility>

#include "fapc/speech/phoneme_visemes.hpp"

namespace fapc::speech {
namespace {

using Entry = std::pair<std::string_view, int>;

// Mnemonics every eSpeak NG language uses alike (its English set, mostly).
constexpr Entry kCommon[] = {
    {"h", 0},   {"?", 0},   {"p", 1},    {"b", 1},    {"m", 1},    {"pF", 1},  {"f", 2},   {"v", 2},   {"T", 3},
    {"D", 3},   {"t", 4},   {"d", 4},    {"t#", 4},   {"k", 5},    {"g", 5},   {"x", 5},   {"q", 5},   {"G", 5},
    {"tS", 6},  {"dZ", 6},  {"S", 6},    {"Z", 6},    {"s", 7},    {"z", 7},   {"ts", 7},  {"dz", 7},  {"C", 7},
    {"z2", 7},  {"n", 8},   {"l", 8},    {"N", 8},    {"n^", 8},   {"l^", 8},  {"@L", 8},  {"L", 8},   {"r", 9},
    {"R", 9},   {"*", 9},   {"r-", 9},   {"R2", 9},   {"a", 10},   {"A", 10},  {"A:", 10}, {"a:", 10}, {"V", 10},
    {"aI", 10}, {"aU", 10}, {"A@", 10},  {"aI@", 10}, {"aU@", 10}, {"a-", 10}, {"A~", 10}, {"a~", 10}, {"e", 11},
    {"e:", 11}, {"E", 11},  {"E:", 11},  {"@", 11},   {"@2", 11},  {"@5", 11}, {"@-", 11}, {"3", 11},  {"3:", 11},
    {"a#", 11}, {"eI", 11}, {"e@", 11},  {"E~", 11},  {"{", 11},   {"i", 12},  {"i:", 12}, {"I", 12},  {"I2", 12},
    {"I#", 12}, {"i@", 12}, {"i@3", 12}, {"j", 12},   {"I@", 12},  {"0", 13},  {"o", 13},  {"o:", 13}, {"O", 13},
    {"O:", 13}, {"oU", 13}, {"OI", 13},  {"OY", 13},  {"o@", 13},  {"O@", 13}, {"O~", 13}, {"W", 13},  {"W~", 13},
    {"2", 13},  {"2:", 13}, {"9", 13},   {"u", 14},   {"u:", 14},  {"U", 14},  {"U@", 14}, {"w", 14},  {"y", 14},
    {"y:", 14}, {"Y:", 14},
};

// Where a language's mnemonic is another sound than the common one.
constexpr Entry kFrench[] = {
    {"Y", 13},  // ø (deux): rounded mid
};
constexpr Entry kGerman[] = {
    {"3", 10},  // ɐ (vocalic r, "Vater"): open, not the English ɜ
    {"Y", 14},  // ʏ (Hütte): rounded close
};

int find(const Entry* table, std::size_t size, std::string_view mnemonic) {
  for (std::size_t i = 0; i < size; ++i)
    if (table[i].first == mnemonic) return table[i].second;
  return -1;
}

int lookup(std::string_view language, std::string_view mnemonic) {
  if (language == "fr") {
    if (const int v = find(kFrench, std::size(kFrench), mnemonic); v >= 0) return v;
  } else if (language == "de") {
    if (const int v = find(kGerman, std::size(kGerman), mnemonic); v >= 0) return v;
  }
  return find(kCommon, std::size(kCommon), mnemonic);
}

bool is_variant_mark(char c) { return c == '#' || c == '-' || c == ':' || c == ';' || c == '/' || c == '.'; }

}  // namespace

int viseme_of_espeak_phoneme(std::string_view language, std::string_view mnemonic) {
  if (!mnemonic.empty() && mnemonic[0] == '_') return 0;  // pauses: _ _: _! _| ...
  const std::string_view base = language.substr(0, language.find('-'));
  while (!mnemonic.empty()) {
    if (const int v = lookup(base, mnemonic); v >= 0) return v;
    if (!is_variant_mark(mnemonic.back())) break;
    mnemonic.remove_suffix(1);
  }
  return -1;
}

}  // namespace fapc::speech

// The behaviour lexicon (docs/intentions.md): what an agent's intention (an FML-APML or APML
// emotion, performative, emphasis, deictic, ...) shows on the face and head, as BML-level
// behaviours (face lexemes, action units, head movements, gaze) placed at fractions of the
// intention's span. fapc's own table is data/intentions.tsv, each row with its reason; a user's
// file (--lexicon) replaces it and is read by the same parser, with the same positioned errors.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::vocabulary {

// What a row draws, in BML's terms.
enum class LexiconBehaviour {
  lexeme,     // a BML faceLexeme (bml_lexemes.tsv); amount is its weight
  unit,       // a FACS action unit (au_faps.tsv), L/R prefix for one side; amount 0..1 of full intensity
  head,       // a BML head lexeme (NOD, SHAKE, TILT, TILT_LEFT, TILT_RIGHT), `*N` for N repetitions; amount as BML's
  gaze,       // the eyes turned towards a direction (LEFT, RIGHT, UP, DOWN, UPLEFT, ...); amount in degrees
  head_turn,  // the head turned towards a direction and back; amount in degrees
  none,       // nothing drawn on purpose (an arm gesture, the listener straight ahead): the span is kept
};

struct LexiconRow {
  std::string intention;  // "emotion", "performative", ... (as the element or attribute names it)
  std::string value;      // "joy", "inform", ...; "*" for every value of the intention
  LexiconBehaviour behaviour = LexiconBehaviour::none;
  std::string name;    // the lexeme, head lexeme or direction as written
  int unit = 0;        // LexiconBehaviour::unit: the action unit
  char side = 'B';     // LexiconBehaviour::unit: L, R or B
  int repetition = 1;  // LexiconBehaviour::head
  double amount = 0;
  // Fractions of the span (0..1, non-decreasing): the behaviour starts, reaches its peak (BML's
  // ready, a nod's first extreme), starts to relax, and ends.
  double start = 0, ready = 0, relax = 1, end = 1;
  std::string reason;
  int line = 0;
};

struct BehaviourLexicon {
  std::string source;  // "intentions.tsv" for the bundled one, else the user's path
  std::vector<LexiconRow> rows;
  // A user's lexicon extends fapc's: what it does not name is looked up in `base` (null: alone).
  const BehaviourLexicon* base = nullptr;

  // The rows of an intention's value (compared without case), else of its "*" rows; an `affect`
  // without rows of its own is read as an `emotion`; then the same in `base`. Empty: the
  // intention is unknown.
  std::vector<const LexiconRow*> rows_for(std::string_view intention, std::string_view value) const;
  // Whether any row names the intention (with any value).
  bool knows(std::string_view intention) const;
};

// A lexicon of more rows than this is refused before it is stored.
inline constexpr std::size_t kMaxLexiconRows = 10000;

// Reads a lexicon: '#' lines and empty lines skipped; the header
// `intention value behaviour name amount start ready relax end reason`, tab separated. Every error
// points at its line and column: an unknown behaviour, lexeme, action unit (or one no FAP
// carries), head lexeme or direction, an amount that is not a number, fractions outside 0..1 or
// out of order, an empty reason.
Result<BehaviourLexicon> parse_behaviour_lexicon(std::string_view text, const std::string& file);

// The bundled lexicon (data/intentions.tsv), parsed once.
const BehaviourLexicon& bundled_behaviour_lexicon();

}  // namespace fapc::vocabulary

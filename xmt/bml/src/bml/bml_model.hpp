// What the BML reader builds from a block before scheduling and lowering: its behaviours (what
// each draws, with its default sync offsets for the solver) and the relations between their sync
// points. lower_block() turns a solved block into clips.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bml/sync_solver.hpp"
#include "fapc/codec/diagnostic.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fapc/transcoder/speech.hpp"
#include "fapc/vocabulary/behaviour_lexicon.hpp"

namespace fapc::bml {

enum class BehaviourKind : std::uint8_t {
  face_lexeme,     // faceLexeme, faceShift lexeme=: a lexeme through its action units
  face_facs,       // faceFacs: one action unit
  gaze,            // gaze, gazeShift: the eyes (and head) turned by offsetAngle/offsetDirection
  head,            // head: a lexeme (NOD, SHAKE, TILT...) repeated
  head_direction,  // headDirectionShift: the head turned and held
  speech,          // speech: visemes and the voice
  lips,            // lips (SmartBody): one recorded viseme, through smartbody_visemes.tsv
  wait,            // wait: time only
  not_drawn,       // gesture, posture, locomotion, pointing, torso...: time only, reported once per kind
  lexicon_rows,    // a Greta reference (docs/bml.md, "Greta references"): behaviour lexicon rows over the span
};

// What a speech says: its visemes and voice, and the time of each of its sync marks.
struct SpokenText {
  std::vector<VisemeSpan> visemes;
  AudioClip audio;  // no samples when spoken by the letter table
  double duration = 0;
  bool recorded = false;  // its audio and times come from a recording, not from synthesis
  std::vector<std::string> mark_ids;
  std::vector<double> mark_times;  // seconds from the speech's start, per mark
};

// The speech a behaviour owns: held apart (most behaviours have none, and a speech is large), and
// copied with the behaviour, so that a copy of a behaviour (SMIL-Agent places one shape many
// times) is whole, whatever fields Behaviour gains.
class OwnedSpeech {
 public:
  OwnedSpeech() = default;
  OwnedSpeech(std::unique_ptr<SpokenText> speech) : speech_(std::move(speech)) {}  // NOLINT: as unique_ptr
  OwnedSpeech(const OwnedSpeech& other)
      : speech_(other.speech_ ? std::make_unique<SpokenText>(*other.speech_) : nullptr) {}
  OwnedSpeech& operator=(const OwnedSpeech& other) { return *this = OwnedSpeech(other); }
  OwnedSpeech(OwnedSpeech&&) = default;
  OwnedSpeech& operator=(OwnedSpeech&&) = default;
  explicit operator bool() const { return speech_ != nullptr; }
  SpokenText* operator->() const { return speech_.get(); }
  SpokenText& operator*() const { return *speech_; }

 private:
  std::unique_ptr<SpokenText> speech_;
};

struct Behaviour {
  BehaviourKind kind = BehaviourKind::wait;
  bool shift = false;  // faceShift, gazeShift, headDirectionShift: the new state holds afterwards
  std::string id;
  std::string element;  // the element's local name
  Location where;
  std::string lexeme;  // faceLexeme, head
  double amount = 1;
  int au = 0;                    // faceFacs
  char side = 'B';               // faceFacs: L, R or B(oth)
  int repetition = 1;            // head
  int viseme = 0;                // lips: the MPEG-4 viseme (0: rest); amount is its articulation
  double offset_angle = 0;       // gaze, headDirectionShift: degrees
  std::string offset_direction;  // RIGHT, LEFT, UP, DOWN, UPRIGHT, ...
  std::string influence;         // gaze: EYES, HEAD, NECK, ...
  OwnedSpeech speech;
  // lexicon_rows: the rows (of greta_references.tsv or intentions.tsv, which outlive the reader),
  // each with its share of `amount`; gretabml's expressivity as docs/bml.md's rule reads it.
  std::vector<const vocabulary::LexiconRow*> rows;
  std::vector<double> row_shares;
  double onset_scale = 1;       // TMP: the onset and offset last this much of the row's
  double repetition_scale = 1;  // REP: head movements repeat this much more
};

// One block: its behaviours (the solver's view beside them) and relations.
struct Block {
  std::string id;
  std::string character;
  enum class Composition : std::uint8_t { merge, append, replace } composition = Composition::merge;
  Location where;
  std::vector<Behaviour> behaviours;
  std::vector<SolverBehaviour> timing;
  std::vector<Relation> relations;
};

// Where a relation came from (Relation::label indexes these): the attribute or sync element, and
// its text, for the errors that name chains.
struct ConstraintSource {
  Location where;
  std::string text;  // `nod1 start="speech1:s1+1"`
};

// The clips of one behaviour at its solved points (seconds from `origin`): the one lowering of
// behaviours to FAPs, called for every behaviour of a block and for every behaviour the intentions
// of FML-APML and APML become (fapc::intent, docs/intentions.md).
void lower_behaviour(const Behaviour& b, const std::array<double, kStandardPoints>& t, double origin,
                     const Coarticulation& rule, Timeline& out, Diagnostics& warnings);

// The clips of one solved block, at `origin` seconds (the block's start).
void lower_block(const Block& block, const Solution& solution, double origin, const Coarticulation& rule, Timeline& out,
                 Diagnostics& warnings);

}  // namespace fapc::bml

// The BML reader: walks a bml block, builds its behaviours and the relations between their sync
// points (bml_model.hpp), solves them (sync_solver.hpp) and lowers the result (lower_block). What
// it does not draw or read is reported, once per kind, never dropped silently.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <unordered_map>

#include <libxml/tree.h>

#include "bml/behaviour_defaults.hpp"
#include "bml/block_reader.hpp"
#include "bml/bml_model.hpp"
#include "bml/facefx_curves.hpp"
#include "bml/greta_reference.hpp"
#include "bml/recorded_speech.hpp"
#include "bml/smartbody_visemes.hpp"
#include "bml/speak_text.hpp"
#include "bml/sync_ref.hpp"
#include "fapc/bml/bml.hpp"
#include "fapc/bml/codes.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/xml/once_per_name.hpp"
#include "fapc/xml/text.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::bml {
namespace {

constexpr std::string_view kBml10 = "http://www.bml-initiative.org/bml/bml-1.0";

std::string format_seconds(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g s", v);
  return buffer;
}

std::string upper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::toupper(c); });
  return out;
}

// The standard sync points by name; attackPeak is a face's ready.
std::optional<std::uint32_t> standard_point(std::string_view name) {
  static const std::map<std::string_view, std::uint32_t> kNames = {
      {"start", kStart},   {"ready", kReady},         {"attackPeak", kReady}, {"strokeStart", kStrokeStart},
      {"stroke", kStroke}, {"strokeEnd", kStrokeEnd}, {"relax", kRelax},      {"end", kEnd}};
  const auto found = kNames.find(name);
  if (found == kNames.end()) return std::nullopt;
  return found->second;
}

const char* kPointNames[kStandardPoints] = {"start", "ready", "strokeStart", "stroke", "strokeEnd", "relax", "end"};

// Behaviours fapc does not draw: their timing is kept (others may sync to them).
bool is_not_drawn(std::string_view name) {
  static const std::set<std::string_view> kNames = {"gesture", "posture", "postureShift", "locomotion", "pointing",
                                                    "torso",   "stance",  "pose",         "curves"};
  return kNames.count(name) != 0;
}

// A relation waiting for every behaviour of the block to be known (references may point forward).
struct Pending {
  Relation::Kind kind = Relation::Kind::equal;
  std::uint32_t behaviour = 0;  // the side the attribute belongs to (a), or for sync pairs
  std::uint32_t point = 0;
  std::optional<SyncRef> a_ref;  // when a is itself a reference (a constraint's sync)
  SyncRef b;                     // the reference: t(a) = t(b) + b.offset (or >=)
  double a_offset = 0;           // a's own offset: t(a) + a_offset ... (constraints)
  bool reversed = false;         // at_least the other way round (before)
  bool self = false;             // b is this behaviour's own start (Greta's times within a behaviour)
  int label = 0;
  const xmlNode* node = nullptr;
  std::string attribute;
};

class BmlReader {
 public:
  BmlReader(const xml::XmlDocument& doc, const ReaderOptions& options, EarlierBlocks* earlier = nullptr)
      : doc_(doc), options_(options), once_(out_.warnings), earlier_(earlier) {}

  // `root`: the document's root, or a bml element inside another language's document (FML-APML's
  // bml part), whose parser warnings that document's reader reports itself.
  Result<BmlDocument> run(const xmlNode* root, bool whole_document) {
    if (root == nullptr)
      return make_error(codes::bml::empty_document, Location{doc_.file(), 1, 1}, "an empty document");
    if (xml::local_name(root) != "bml")
      return doc_.error(codes::bml::not_bml, root,
                        "the root element is <" + std::string(xml::local_name(root)) + ">, not a BML <bml> block");
    out_.dialect = dialect_of(root);
    Block block;
    if (!read_block(root, block)) return *error_;
    if (!schedule(block, origin_)) return *error_;
    once_.finish();
    if (whole_document)
      for (const Diagnostic& w : doc_.warnings()) out_.warnings.push_back(w);
    return std::move(out_);
  }

 private:
  const xml::XmlDocument& doc_;
  const ReaderOptions& options_;
  BmlDocument out_;
  xml::OncePerName once_;
  std::optional<Diagnostic> error_;
  std::vector<ConstraintSource> sources_;
  bool warned_no_engine_ = false;
  std::set<const xmlNode*> overruled_;  // recorded speeches whose placeholder times were said
  std::int64_t counted_ = 0;
  // A block of a sequence: the blocks before it, and where its composition placed it.
  EarlierBlocks* earlier_ = nullptr;
  double origin_ = 0;

  // The dialect (docs/bml.md, "Dialects"): BML 1.0 by its namespace; Greta/SEMAINE by its
  // gretabml descriptions or the older mindmakers namespace; SmartBody by its lips, curves and
  // recorded speech.
  std::string dialect_of(const xmlNode* root) const {
    const std::string_view ns = xml::namespace_uri(root);
    if (ns == kBml10) return "BML 1.0";
    bool greta = ns.find("mindmakers") != std::string_view::npos;
    bool smartbody = false;
    for (const xmlNode* child : doc_.children(root)) {
      const std::string_view name = xml::local_name(child);
      if (name == "lips" || name == "curves") smartbody = true;
      for (const xmlNode* inner : doc_.children(child)) {
        if (xml::local_name(inner) != "description") continue;
        const std::string type = xml::attribute(inner, "type").value_or("");
        if (type == "gretabml") greta = true;
        if (type.starts_with("audio/")) smartbody = true;
      }
    }
    if (smartbody) return "SmartBody";
    if (greta) return "Greta/SEMAINE";
    return "BML (no namespace)";
  }

  bool fail(Diagnostic d) {
    if (!error_) error_ = std::move(d);
    return false;
  }

  int label(const xmlNode* node, std::string_view attribute, std::string text) {
    sources_.push_back({attribute.empty() ? doc_.where(node) : doc_.where(node, attribute), std::move(text)});
    return static_cast<int>(sources_.size() - 1);
  }

  bool count_one(const xmlNode* node) {
    if (++counted_ <= options_.limits.max_runs) return true;
    return fail(doc_.error(codes::limit::runs, node,
                           "more than " + std::to_string(options_.limits.max_runs) +
                               " behaviours and constraints (raise the limit with --max-runs)"));
  }

  bool read_block(const xmlNode* root, Block& block) {
    block.where = doc_.where(root);
    block.id = xml::attribute(root, "id").value_or("");
    block.character = xml::attribute(root, "characterId").value_or(xml::attribute(root, "character").value_or(""));
    if (const auto composition = xml::attribute(root, "composition")) {
      const std::string c = upper(xml::trim(*composition));
      if (c == "MERGE")
        block.composition = Block::Composition::merge;
      else if (c == "APPEND")
        block.composition = Block::Composition::append;
      else if (c == "REPLACE")
        block.composition = Block::Composition::replace;
      else
        return fail(doc_.error(codes::bml::bad_composition, root, "composition",
                               "composition '" + *composition + "' is not MERGE, APPEND or REPLACE"));
    }
    static const char* const kCompositionNames[] = {"MERGE", "APPEND", "REPLACE"};
    out_.compositions.emplace_back(kCompositionNames[static_cast<int>(block.composition)]);
    if (earlier_ != nullptr) {
      origin_ = earlier_->arrival;
      if (block.composition == Block::Composition::append) origin_ = std::max(origin_, earlier_->end);
    }
    out_.block_starts.push_back(origin_);
    out_.blocks.push_back(block.id);
    out_.characters.push_back(block.character);
    std::vector<Pending> pending;
    std::vector<const xmlNode*> constraints;
    for (const xmlNode* child : doc_.children(root)) {
      const std::string_view name = xml::local_name(child);
      if (name == "constraint" || name == "required") {
        constraints.push_back(child);
        continue;
      }
      if (!count_one(child)) return false;
      if (!read_behaviour(child, block, pending)) return false;
    }
    settle_mouth(block);
    for (const xmlNode* c : constraints)
      if (!read_constraint(c, block, pending)) return false;
    return resolve(block, pending);
  }

  // A block's lips rows are its mouth (the shapes of recorded audio): they win over the visemes
  // of synthesised speech. Recorded speech without lips has no mouth at all: fapc does not find
  // the phonemes of audio. Each said once.
  void settle_mouth(Block& block) {
    const bool lips = std::any_of(block.behaviours.begin(), block.behaviours.end(),
                                  [](const Behaviour& b) { return b.kind == BehaviourKind::lips; });
    for (Behaviour& b : block.behaviours) {
      if (!b.speech) continue;
      if (lips && !b.speech->visemes.empty()) {
        b.speech->visemes.clear();
        once_.report("lips over synthesis",
                     with_code(make_warning(b.where,
                                            "the block's <lips> rows move the mouth: the visemes "
                                            "synthesised for this speech are not drawn",
                                            doc_.line_text(b.where.line)),
                               codes::bml::lips_over_synthesis));
      } else if (!lips && b.speech->recorded) {
        once_.report("recorded without lips",
                     with_code(make_warning(b.where,
                                            "recorded speech without <lips> rows: fapc does not find the phonemes "
                                            "of audio, so the mouth does not follow it",
                                            doc_.line_text(b.where.line)),
                               codes::bml::recorded_speech_without_lips));
      }
    }
  }

  // ---- behaviours -------------------------------------------------------------------------

  bool read_behaviour(const xmlNode* node, Block& block, std::vector<Pending>& pending) {
    const std::string_view name = xml::local_name(node);
    Behaviour b;
    b.element = std::string(name);
    b.where = doc_.where(node);
    b.id = xml::attribute(node, "id").value_or("");
    b.amount = number_attribute(node, "amount", 1.0);
    if (error_) return false;
    const std::string_view ns = xml::namespace_uri(node);
    const bool core = ns.empty() || ns == kBml10 || ns.find("mindmakers") != std::string_view::npos;
    if (!core || is_not_drawn(name)) {
      b.kind = BehaviourKind::not_drawn;
      once_.report(
          "not drawn " + b.element,
          with_code(doc_.warning(node, "<" + b.element + "> is not drawn by fapc (no body): its timing is kept"),
                    codes::bml::not_drawn));
    } else if ((name == "face" || name == "head" || name == "gaze") && greta_reference(node, b)) {
      // Greta's reference names (docs/bml.md, "Greta references"): read by greta_reference.cpp
    } else if (name == "lips" || name == "lip") {
      read_lips(node, b);
    } else if (name == "face" && upper(xml::trim(xml::attribute(node, "type").value_or(""))) == "FACS") {
      // SmartBody's <face type="facs" au="N" amount=>: BML 1.0's faceFacs under another name.
      if (!read_facs(node, b)) return false;
    } else if (name == "faceLexeme" || name == "faceShift" || name == "face") {
      b.kind = BehaviourKind::face_lexeme;
      b.shift = name == "faceShift";
      b.lexeme = xml::attribute(node, "lexeme").value_or("");
      if (b.lexeme.empty()) b.kind = BehaviourKind::not_drawn;
    } else if (name == "faceFacs") {
      if (!read_facs(node, b)) return false;
    } else if (name == "gaze" || name == "gazeShift") {
      b.kind = BehaviourKind::gaze;
      b.shift = name == "gazeShift";
      read_direction(node, b);
      b.influence = upper(xml::trim(xml::attribute(node, "influence").value_or("EYES")));
    } else if (name == "head") {
      b.kind = BehaviourKind::head;
      // SmartBody names the lexeme `type` (<head type="NOD"/>).
      b.lexeme = upper(xml::trim(xml::attribute(node, "lexeme").value_or(xml::attribute(node, "type").value_or(""))));
      // Checked as a double: a huge value converted to int first is undefined (found by fuzzing).
      const double repetition = number_attribute(node, "repetition", 1.0);
      if (!(repetition >= 1 && repetition <= 100) || repetition != std::floor(repetition))
        return fail(
            doc_.error(codes::bml::bad_value, node, "repetition", "repetition must be a whole number from 1 to 100"));
      b.repetition = static_cast<int>(repetition);
    } else if (name == "headDirectionShift") {
      b.kind = BehaviourKind::head_direction;
      b.shift = true;
      read_direction(node, b);
    } else if (name == "speech") {
      b.kind = BehaviourKind::speech;
      if (!read_speech(node, b)) return false;
    } else if (name == "wait") {
      b.kind = BehaviourKind::wait;
    } else {
      b.kind = BehaviourKind::not_drawn;
      once_.report(
          "unknown " + b.element,
          with_code(doc_.warning(
                        node, "<" + b.element + "> is not a BML 1.0 behaviour: its timing is kept, nothing is drawn"),
                    codes::bml::unknown_behaviour));
    }
    if (error_) return false;
    if (b.id.empty()) b.id = "#" + std::to_string(block.behaviours.size() + 1);
    SolverBehaviour timing;
    timing.defaults = default_offsets(b);
    if (b.kind == BehaviourKind::speech) {
      timing.rigid = true;
      timing.marks = b.speech->mark_times;
      timing.own_label = label(node, "", b.id + " lasts " + format_seconds(b.speech->duration) + " as spoken");
    }
    const auto index = static_cast<std::uint32_t>(block.behaviours.size());
    const std::size_t timed_before = pending.size();
    // Greta 0.x (SEMAINE) writes a behaviour's later points as times within it: a plain time
    // earlier than a plain start is read from the start (docs/bml.md, "Dialects").
    std::optional<double> plain_start;
    if (out_.dialect != "BML 1.0")
      if (const auto start = xml::attribute(node, "start")) plain_start = parse_seconds(*start);
    for (std::uint32_t p = 0; p < kStandardPoints; ++p) {
      const char* attribute = kPointNames[p];
      std::optional<std::string> value = xml::attribute(node, attribute);
      if (!value && p == kReady) {
        value = xml::attribute(node, "attackPeak");
        if (value) attribute = "attackPeak";
      }
      if (!value) continue;
      std::string why;
      const auto ref = parse_sync_ref(*value, why);
      if (!ref) return fail(doc_.error(codes::bml::bad_reference, node, attribute, why));
      if (p != kStart && b.speech && b.speech->recorded && overruled_by_recording(node, b, timing, p, attribute, *ref))
        continue;
      Pending p_;
      p_.behaviour = index;
      p_.point = p;
      p_.b = *ref;
      if (p != kStart && plain_start && ref->absolute && ref->offset < *plain_start) {
        p_.b.absolute = false;
        p_.b.behaviour = b.id;
        p_.b.sync = "start";
        p_.self = true;
        once_.report("relative time",
                     with_code(doc_.warning(node, attribute,
                                            std::string(attribute) + " is earlier than start: read as "
                                                                     "a time from the behaviour's start (Greta 0.x)"),
                               codes::bml::time_from_start));
      }
      p_.label = label(node, attribute, b.id + " " + attribute + "=\"" + std::string(xml::trim(*value)) + "\"");
      p_.node = node;
      p_.attribute = attribute;
      pending.push_back(std::move(p_));
    }
    if (name == "curves" && pending.size() == timed_before) time_curves(node, b, index, pending);
    block.behaviours.push_back(std::move(b));
    block.timing.push_back(std::move(timing));
    return true;
  }

  // FaceFX curves with no timing attributes last from their first key to their last (times from
  // the utterance's start, which NVBG puts at the block's): their own timing, not a gesture's default.
  void time_curves(const xmlNode* node, const Behaviour& b, std::uint32_t index, std::vector<Pending>& pending) {
    const auto extent = curves_extent(doc_, node);
    if (!extent) return;
    for (const auto& [point, seconds] : {std::pair{kStart, extent->first}, std::pair{kEnd, extent->second}}) {
      Pending p;
      p.behaviour = index;
      p.point = point;
      p.b.absolute = true;
      p.b.offset = seconds;
      p.label = label(node, "", b.id + " " + kPointNames[point] + " at its keys' " + format_seconds(seconds));
      p.node = node;
      pending.push_back(std::move(p));
    }
  }

  // NVBG writes placeholder times on recorded speech (ready="0.1" ... end="0.2" for a second of
  // words): a plain time that disagrees with the recording (by more than a millisecond) is not
  // read; the recording wins, said once per speech at the first such attribute (docs/bml.md).
  bool overruled_by_recording(const xmlNode* node, const Behaviour& b, const SolverBehaviour& timing, std::uint32_t p,
                              const char* attribute, const SyncRef& ref) {
    if (!ref.absolute) return false;  // a reference is a constraint of the user's: the solver checks it
    std::optional<double> start = 0.0;
    if (const auto text = xml::attribute(node, "start")) start = parse_seconds(*text);
    if (!start) return false;  // the start is itself a reference: the solver checks the plain time
    const double recorded = *start + timing.defaults[p];
    if (std::abs(ref.offset - recorded) <= 1e-3) return false;
    if (overruled_.insert(node).second)
      out_.warnings.push_back(with_code(
          doc_.warning(node, attribute,
                       std::string(attribute) + "=\"" + std::string(xml::trim(*xml::attribute(node, attribute))) +
                           "\" contradicts the recording of '" + b.id + "' (" + std::string(attribute) + " at " +
                           format_seconds(recorded) + ", " + format_seconds(b.speech->duration) +
                           " long by its marks and audio): "
                           "the recorded timing wins, and the speech's other placeholder times are not read"),
          codes::bml::recorded_timing_wins));
    return true;
  }

  // A face, head or gaze with a gretabml reference becomes that reference's rows; false (and
  // error_ unset) when it has none.
  bool greta_reference(const xmlNode* node, Behaviour& b) {
    Result<bool> read = read_greta_reference(doc_, node, b, once_);
    if (!read) return !fail(read.error());
    return *read;
  }

  // <lips viseme="BMP" articulation="1.0"/>: one viseme of a recording (SmartBody), through
  // smartbody_visemes.tsv. An unknown name keeps its timing and moves nothing.
  void read_lips(const xmlNode* node, Behaviour& b) {
    b.kind = BehaviourKind::lips;
    b.amount = std::clamp(number_attribute(node, "articulation", 1.0), 0.0, 1.0);
    const std::string name(xml::trim(xml::attribute(node, "viseme").value_or("")));
    const auto viseme = smartbody_viseme(name);
    if (viseme) {
      b.viseme = *viseme;
      return;
    }
    std::string known;
    for (const std::string& n : smartbody_viseme_names()) known += (known.empty() ? "" : " ") + n;
    once_.report("viseme " + name, with_code(doc_.warning(node, "viseme",
                                                          "viseme '" + name + "' is not one of SmartBody's (" + known +
                                                              "): its timing is kept, the mouth does not move"),
                                             codes::bml::unknown_viseme));
  }

  // faceFacs (and SmartBody's face type="facs"): au and side.
  bool read_facs(const xmlNode* node, Behaviour& b) {
    b.kind = BehaviourKind::face_facs;
    const auto au = xml::attribute(node, "au");
    const auto n = au ? xml::decimal(xml::trim(*au)) : std::nullopt;
    if (!n || *n != std::floor(*n) || *n < 1 || *n > 99)
      return fail(doc_.error(codes::bml::missing_attribute, node, "au",
                             "<" + b.element + "> needs au, an action unit number from 1 to 99"));
    b.au = static_cast<int>(*n);
    const std::string side = upper(xml::trim(xml::attribute(node, "side").value_or("BOTH")));
    if (side == "LEFT")
      b.side = 'L';
    else if (side == "RIGHT")
      b.side = 'R';
    else if (side == "BOTH")
      b.side = 'B';
    else
      return fail(doc_.error(codes::bml::bad_value, node, "side", "side '" + side + "' is not LEFT, RIGHT or BOTH"));
    return true;
  }

  static Diagnostic with_code(Diagnostic d, WarningCode code) {
    d.code = code.name;
    return d;
  }

  double number_attribute(const xmlNode* node, const char* name, double fallback) {
    const auto text = xml::attribute(node, name);
    if (!text) return fallback;
    const auto n = xml::decimal(xml::trim(*text));
    if (!n) {
      fail(doc_.error(codes::bml::bad_value, node, name, std::string(name) + " '" + *text + "' is not a number"));
      return fallback;
    }
    return *n;
  }

  void read_direction(const xmlNode* node, Behaviour& b) {
    b.offset_angle = number_attribute(node, "offsetAngle", 0.0);
    b.offset_direction = upper(xml::trim(xml::attribute(node, "offsetDirection").value_or("RIGHT")));
    if (xml::attribute(node, "target"))
      once_.report("target", with_code(doc_.warning(node, "target",
                                                    "gaze and head targets name objects of a world "
                                                    "fapc does not have: taken as straight ahead, "
                                                    "offsetAngle and offsetDirection turn from there"),
                                       codes::bml::target_ahead));
  }

  // <speech><text>words <sync id="s1"/> words</text></speech>, or the text and its tm marks
  // right inside the speech (Greta).
  bool read_speech(const xmlNode* node, Behaviour& b) {
    if (const xmlNode* description = audio_description(doc_, node)) {
      Result<SpokenText> recorded = recorded_speech(doc_, node, description, options_, out_.warnings, out_.recordings);
      if (!recorded) return fail(recorded.error());
      b.speech = std::make_unique<SpokenText>(std::move(*recorded));
      return true;
    }
    const xmlNode* text_node = nullptr;
    for (const xmlNode* child : doc_.children(node))
      if (xml::local_name(child) == "text") text_node = child;
    MarkedText marked;
    collect_text(text_node != nullptr ? text_node : node, marked);
    if (error_) return false;
    Result<SpokenText> spoken = speak(marked, options_, b.where, out_.warnings, warned_no_engine_);
    if (!spoken) return fail(spoken.error());
    if (std::find(out_.languages.begin(), out_.languages.end(), options_.speech.language) == out_.languages.end())
      out_.languages.push_back(options_.speech.language);
    b.speech = std::make_unique<SpokenText>(std::move(*spoken));
    return true;
  }

  void collect_text(const xmlNode* parent, MarkedText& marked) {
    for (const xmlNode* n = parent->children; n != nullptr; n = n->next) {
      if (n->type == XML_TEXT_NODE || n->type == XML_CDATA_SECTION_NODE) {
        if (n->content == nullptr) continue;
        const std::string_view words = xml::trim(reinterpret_cast<const char*>(n->content));
        if (words.empty()) continue;
        if (!marked.text.empty()) marked.text += ' ';
        marked.text += words;
        continue;
      }
      if (n->type != XML_ELEMENT_NODE) continue;
      const std::string_view name = xml::local_name(n);
      if (name == "sync" || name == "tm" || name == "mark") {
        const auto id = xml::attribute(n, "id");
        if (!id || xml::trim(*id).empty()) {
          fail(doc_.error(codes::bml::missing_attribute, n, "<" + std::string(name) + "> in speech needs an id"));
          return;
        }
        marked.mark_ids.emplace_back(xml::trim(*id));
        marked.mark_offsets.push_back(marked.text.empty() ? 0 : marked.text.size() + 1);
      } else if (name != "description" && name != "text") {
        once_.report("in speech " + std::string(name),
                     with_code(doc_.warning(n, "<" + std::string(name) +
                                                   "> in speech is not read (prosody marks): its text is not spoken"),
                               codes::bml::speech_markup_skipped));
      }
    }
  }

  // ---- constraints ------------------------------------------------------------------------

  bool read_constraint(const xmlNode* node, Block& block, std::vector<Pending>& pending) {
    for (const xmlNode* child : doc_.children(node)) {
      const std::string_view name = xml::local_name(child);
      if (name == "constraint") {
        if (!read_constraint(child, block, pending)) return false;
        continue;
      }
      if (!count_one(child)) return false;
      if (name != "synchronize" && name != "before" && name != "after") {
        once_.report(
            "constraint " + std::string(name),
            with_code(doc_.warning(child, "<" + std::string(name) +
                                              "> is not a BML constraint (synchronize, before, after): skipped"),
                      codes::bml::unknown_constraint));
        continue;
      }
      std::optional<SyncRef> anchor;
      const xmlNode* anchor_node = child;
      if (const auto ref = xml::attribute(child, "ref")) {
        std::string why;
        anchor = parse_sync_ref(*ref, why);
        if (!anchor) return fail(doc_.error(codes::bml::bad_reference, child, "ref", why));
      } else if (name != "synchronize") {
        return fail(doc_.error(codes::bml::missing_attribute, child,
                               "<" + std::string(name) + "> needs ref, the sync point the others come " +
                                   (name == "before" ? "before" : "after")));
      }
      for (const xmlNode* sync : doc_.children(child)) {
        if (xml::local_name(sync) != "sync") continue;
        const auto ref_text = xml::attribute(sync, "ref");
        if (!ref_text) return fail(doc_.error(codes::bml::missing_attribute, sync, "<sync> in a constraint needs ref"));
        std::string why;
        const auto ref = parse_sync_ref(*ref_text, why);
        if (!ref) return fail(doc_.error(codes::bml::bad_reference, sync, "ref", why));
        if (!anchor) {  // the first sync of a synchronize is the one the others equal
          anchor = ref;
          anchor_node = sync;
          continue;
        }
        Pending p;
        p.kind = name == "synchronize" ? Relation::Kind::equal : Relation::Kind::at_least;
        p.a_ref = ref;
        p.b = *anchor;
        p.reversed = name == "before";
        p.label = label(sync, "ref",
                        std::string(name) + " " + std::string(xml::trim(*ref_text)) + " with " + describe(*anchor));
        p.node = sync;
        p.attribute = "ref";
        pending.push_back(std::move(p));
      }
      (void)anchor_node;
    }
    return true;
  }

  static std::string describe(const SyncRef& r) {
    if (r.absolute) return format_seconds(r.offset);
    std::string s = (r.block.empty() ? "" : r.block + ":") + r.behaviour + ":" + r.sync;
    if (r.offset != 0) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%+g", r.offset);
      s += buffer;
    }
    return s;
  }

  // A reference to a point of this block: its behaviour and point, or an error at the reference.
  std::optional<PointRef> point_of(const Block& block, const std::unordered_map<std::string, std::uint32_t>& ids,
                                   const SyncRef& ref, const Pending& at) {
    if (!ref.block.empty() && ref.block != block.id) {
      fail(doc_.error(
          codes::bml::unknown_reference, at.node, at.attribute,
          "'" + describe(ref) + "' names the block '" + ref.block + "'; this document's block is '" + block.id + "'"));
      return std::nullopt;
    }
    const auto found = ids.find(ref.behaviour);
    if (found == ids.end()) {
      fail(doc_.error(codes::bml::unknown_reference, at.node, at.attribute,
                      "'" + describe(ref) + "': no behaviour '" + ref.behaviour + "' in block '" + block.id + "'"));
      return std::nullopt;
    }
    const Behaviour& b = block.behaviours[found->second];
    if (const auto p = standard_point(ref.sync)) return PointRef{found->second, *p};
    if (b.speech) {
      const auto& ids_of = b.speech->mark_ids;
      const auto mark = std::find(ids_of.begin(), ids_of.end(), ref.sync);
      if (mark != ids_of.end())
        return PointRef{found->second, kStandardPoints + static_cast<std::uint32_t>(mark - ids_of.begin())};
    }
    fail(doc_.error(codes::bml::unknown_reference, at.node, at.attribute,
                    "'" + describe(ref) + "': " + b.element + " '" + b.id + "' has no sync point '" + ref.sync +
                        "' (start, ready, strokeStart, stroke, strokeEnd, relax, end" +
                        (b.speech ? ", or one of its sync marks)" : ")")));
    return std::nullopt;
  }

  bool resolve(Block& block, const std::vector<Pending>& pending) {
    std::unordered_map<std::string, std::uint32_t> ids;
    for (std::uint32_t i = 0; i < block.behaviours.size(); ++i) {
      const Behaviour& b = block.behaviours[i];
      if (!ids.emplace(b.id, i).second) {
        const Location& first = block.behaviours[ids[b.id]].where;
        if (out_.dialect != "BML 1.0") {
          // Greta's planners reuse ids; BML 1.0 forbids it. References name the first.
          once_.report("duplicate id",
                       with_code(make_warning(b.where,
                                              "a second behaviour with id '" + b.id + "' (the first is at line " +
                                                  std::to_string(first.line) + "): references name the first",
                                              doc_.line_text(b.where.line)),
                                 codes::bml::duplicate_id));
          continue;
        }
        return fail(make_error(
            codes::bml::duplicate_id_error, b.where,
            "a second behaviour with id '" + b.id + "' (the first is at line " + std::to_string(first.line) + ")",
            doc_.line_text(b.where.line)));
      }
    }
    for (const Pending& p : pending) {
      Relation r;
      r.kind = p.kind;
      r.label = p.label;
      PointRef a{p.behaviour, p.point};
      double a_offset = 0;
      SyncRef other = p.b;
      if (!p.self && !from_earlier_block(block, other, p)) return false;
      if (p.a_ref) {
        SyncRef mine = *p.a_ref;
        if (!from_earlier_block(block, mine, p)) return false;
        // <synchronize> may hold a plain time: the others are put at it.
        if (mine.absolute && !other.absolute && p.kind == Relation::Kind::equal) std::swap(mine, other);
        if (mine.absolute)
          return fail(doc_.error(codes::bml::plain_times_compared, p.node, p.attribute,
                                 "this constraint compares two plain times: name a behaviour's sync point"));
        const auto point = point_of(block, ids, mine, p);
        if (!point) return false;
        a = *point;
        a_offset = mine.offset;
      }
      std::optional<PointRef> b;
      if (p.self) {
        b = PointRef{p.behaviour, kStart};
      } else if (!other.absolute) {
        b = point_of(block, ids, other, p);
        if (!b) return false;
      }
      // t(a) + a_offset = t(b) + b.offset  ->  t(a) = t(b) + (b.offset - a_offset)
      double offset = other.offset - a_offset;
      if (p.reversed) {  // before: t(a) + a_offset <= t(b) + b.offset -> t(b) >= t(a) + (a_offset - b.offset)
        if (!b) {
          return fail(doc_.error(codes::bml::before_plain_time, p.node, p.attribute,
                                 "before a plain time is not read: give the time as the sync point's own"));
        }
        r.a = *b;
        r.b = a;
        r.offset = -offset;
      } else {
        r.a = a;
        r.b = b;
        r.offset = offset;
      }
      block.relations.push_back(r);
    }
    return true;
  }

  // A reference to a point of an earlier block of the sequence becomes the plain time it was
  // placed at, from this block's start (docs/bml.md, "Several blocks"). References to this block,
  // or outside a sequence, are left to point_of.
  bool from_earlier_block(const Block& block, SyncRef& ref, const Pending& at) {
    if (earlier_ == nullptr || ref.absolute || ref.block.empty() || ref.block == block.id) return true;
    const auto found = earlier_->placed.find(ref.block);
    if (found == earlier_->placed.end()) {
      std::string known;
      for (const auto& [id, behaviours] : earlier_->placed) known += (known.empty() ? "'" : ", '") + id + "'";
      return fail(doc_.error(codes::bml::unknown_reference, at.node, at.attribute,
                             "'" + describe(ref) + "' names the block '" + ref.block +
                                 "', which is not an earlier block of the sequence (" +
                                 (known.empty() ? std::string("there is none") : "those are " + known) +
                                 "; this block is '" + block.id + "')"));
    }
    const auto behaviour = found->second.find(ref.behaviour);
    if (behaviour == found->second.end())
      return fail(
          doc_.error(codes::bml::unknown_reference, at.node, at.attribute,
                     "'" + describe(ref) + "': no behaviour '" + ref.behaviour + "' in block '" + ref.block + "'"));
    const PlacedPoints& placed = behaviour->second;
    std::optional<double> time;
    if (const auto p = standard_point(ref.sync)) time = placed.points[*p];
    for (std::size_t m = 0; !time && m < placed.mark_ids.size(); ++m)
      if (placed.mark_ids[m] == ref.sync) time = placed.marks[m];
    if (!time)
      return fail(doc_.error(codes::bml::unknown_reference, at.node, at.attribute,
                             "'" + describe(ref) + "': '" + ref.behaviour + "' of block '" + ref.block +
                                 "' has no sync point '" + ref.sync + "'"));
    ref.absolute = true;
    ref.offset = *time + ref.offset - origin_;
    ref.block.clear();
    return true;
  }

  // ---- scheduling -------------------------------------------------------------------------

  bool schedule(const Block& block, double origin) {
    const Solved solved = solve(block.timing, block.relations);
    if (solved.error) return fail(solve_error(block, *solved.error));
    const Solution& s = solved.solution;
    for (std::uint32_t i = 0; i < block.behaviours.size(); ++i) {
      const Behaviour& b = block.behaviours[i];
      out_.behaviours.push_back({block.id, b.id, b.element, origin + s.points[i][kStart], origin + s.points[i][kEnd],
                                 b.kind != BehaviourKind::not_drawn && b.kind != BehaviourKind::wait});
      if (b.speech)
        for (std::size_t m = 0; m < b.speech->mark_ids.size(); ++m)
          out_.marks.push_back({b.id, b.speech->mark_ids[m], origin + s.marks[i][m]});
      if (earlier_ != nullptr) {  // later blocks of the sequence may name this behaviour's points
        PlacedPoints placed;
        for (std::uint32_t p = 0; p < kStandardPoints; ++p) placed.points[p] = origin + s.points[i][p];
        if (b.speech) placed.mark_ids = b.speech->mark_ids;
        for (double m : s.marks[i]) placed.marks.push_back(origin + m);
        earlier_->placed[block.id].emplace(b.id, std::move(placed));  // a reused id: the first is named
      }
    }
    lower_block(block, s, origin, options_.speech.coarticulation, out_.timeline, out_.warnings);
    double end = origin;
    for (const auto& points : s.points) end = std::max(end, origin + points[kEnd]);
    out_.timeline.explicit_end = std::max(out_.timeline.explicit_end.value_or(0.0), end);
    out_.timeline.end_source = block.where;
    if (options_.frames.exceeded_by(end)) return fail(frame_budget_error(end, block.where, options_.frames));
    return true;
  }

  std::string chain_text(const std::vector<int>& chain) const {
    std::string out;
    for (int l : chain) {
      if (l < 0) continue;
      const ConstraintSource& s = sources_[static_cast<std::size_t>(l)];
      out += (out.empty() ? "" : ", then ") + s.text + " (line " + std::to_string(s.where.line) + ")";
    }
    return out;
  }

  Diagnostic at_label(int l, std::string message) const {
    const ConstraintSource& s = sources_[static_cast<std::size_t>(std::max(0, l))];
    return make_error(codes::bml::constraints_conflict, s.where, std::move(message), doc_.line_text(s.where.line));
  }

  Diagnostic solve_error(const Block& block, const SolveError& e) const {
    const std::string what =
        e.label >= 0 ? sources_[static_cast<std::size_t>(e.label)].text : std::string("the timing");
    const std::string chain = chain_text(e.chain);
    switch (e.what) {
      case SolveError::What::contradiction:
        if (e.absolute)
          return at_label(e.label, what + " cannot hold: it asks for " + format_seconds(e.time) +
                                       " from the block's start, but " + chain + " already put that point at " +
                                       format_seconds(e.other_time));
        return at_label(e.label, what + " cannot hold: it asks for its two points " + format_seconds(e.time) +
                                     " apart, but " + chain + " already put them " + format_seconds(e.other_time) +
                                     " apart");
      case SolveError::What::order: {
        const Behaviour& b = block.behaviours[e.behaviour];
        return at_label(e.label, what + " cannot hold: it puts " + b.id + ":" + kPointNames[e.point] + " at " +
                                     format_seconds(e.time) + ", before " + b.id + ":" + kPointNames[e.other] + " at " +
                                     format_seconds(e.other_time) + (chain.empty() ? "" : " (set by " + chain + ")"));
      }
      case SolveError::What::before_block: {
        const Behaviour& b = block.behaviours[e.behaviour];
        return at_label(e.label, what + " cannot hold: " + b.id + " would start at " + format_seconds(e.time) +
                                     ", before its block" + (chain.empty() ? "" : " (" + chain + ")"));
      }
      case SolveError::What::unmet:
        return at_label(e.label, what + " cannot hold: it needs " + format_seconds(e.time) +
                                     " or later, but the times fixed " +
                                     (chain.empty() ? std::string("elsewhere") : "by " + chain) + " give " +
                                     format_seconds(e.other_time));
    }
    return at_label(e.label, what + " cannot hold");
  }
};

}  // namespace

Result<BmlDocument> read_bml(std::string_view text, const std::string& file_name, const ReaderOptions& options) {
  if (const Status depth = xml::check_element_depth(text, file_name); !depth) return depth.error();
  // Only speech text is read; elsewhere white space is dropped.
  const xml::BlankText blank_text{false, {"text", "speech"}};
  Result<xml::XmlDocument> doc = xml::XmlDocument::parse(text, file_name, blank_text);
  if (!doc) return doc.error();
  return BmlReader(*doc, options).run(doc->root(), true);
}

Result<BmlDocument> read_bml_block(const xml::XmlDocument& doc, const xmlNode* block, const ReaderOptions& options) {
  return BmlReader(doc, options).run(block, false);
}

Result<BmlDocument> read_sequenced_block(const xml::XmlDocument& doc, const ReaderOptions& options,
                                         EarlierBlocks& earlier) {
  return BmlReader(doc, options, &earlier).run(doc.root(), true);
}

Result<BmlDocument> load_bml(const std::string& path, const ReaderOptions& options) {
  const auto source = SourceText::open(path);
  if (!source) return source.error();
  return read_bml(source->bytes(), path, options);
}

}  // namespace fapc::bml

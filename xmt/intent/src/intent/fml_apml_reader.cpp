// Greta's FML-APML (docs/intentions.md): the bml part is read as a BML block (speech with its tm
// marks, behaviours), then each intention of the fml part is placed on its span, whose start and
// end are times or references to the speech's marks, the bml part's behaviours or other
// intentions, and drawn through the behaviour lexicon.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "bml/block_reader.hpp"
#include "bml/sync_ref.hpp"
#include "fapc/intent/codes.hpp"
#include "fapc/xml/text.hpp"
#include "intent/document_reader.hpp"
#include "intent/realize.hpp"

namespace fapc::intent {
namespace {

constexpr double kMaxSeconds = 1e7;

// An intention waiting for its span: its element, and whether its times are being resolved (a
// reference cycle is found when one is met again while it is).
struct Pending {
  const xmlNode* node = nullptr;
  Intention intention;
  enum class State : std::uint8_t { open, resolving, done } state = State::open;
};

class FmlApmlReader : public DocumentReader {
 public:
  FmlApmlReader(const xml::XmlDocument& doc, const IntentOptions& options) : DocumentReader(doc, options, "FML-APML") {}

  Result<IntentDocument> run() {
    Result<const xmlNode*> root = root_named("fml-apml");
    if (!root) return root.error();
    std::vector<const xmlNode*> fml_parts;
    for (const xmlNode* part : doc_.children(*root)) {
      const std::string_view name = xml::local_name(part);
      if (name == "bml") {
        if (Status read = read_bml_part(part); !read) return read.error();
      } else if (name == "fml") {
        fml_parts.push_back(part);
      } else {
        once_.report(
            "part " + std::string(name),
            with_code(doc_.warning(part, "<" + std::string(name) + "> is neither the bml nor the fml part: not read"),
                      codes::intent::unknown_part));
      }
    }
    for (const xmlNode* fml : fml_parts)
      for (const xmlNode* node : doc_.children(fml)) {
        if (Status counted = count(node, "intentions"); !counted) return counted.error();
        if (Status added = add(node); !added) return added.error();
      }
    for (Pending& p : pending_)
      if (Status placed = place(p); !placed) return placed.error();
    std::vector<Intention> intentions;
    intentions.reserve(pending_.size());
    for (Pending& p : pending_) intentions.push_back(std::move(p.intention));
    const bool spoken = out_.timeline.explicit_end.has_value();
    return draw_and_finish(std::move(intentions), out_.timeline.explicit_end.value_or(0.0),
                           spoken ? out_.timeline.end_source : doc_.where(*root));
  }

 private:
  std::vector<Pending> pending_;
  std::map<std::string, std::size_t> intention_ids_;
  // The bml part's speech marks (speech id, mark id) and behaviours (id) with their times.
  std::map<std::pair<std::string, std::string>, double> marks_;
  std::vector<bml::ScheduledMark> mark_order_;  // in document order, for messages
  std::map<std::string, std::pair<double, double>> behaviours_;

  Status read_bml_part(const xmlNode* part) {
    Result<bml::BmlDocument> block = bml::read_bml_block(doc_, part, options_);
    if (!block) return block.error();
    for (Clip& clip : block->timeline.clips) out_.timeline.clips.push_back(std::move(clip));
    for (AudioClip& audio : block->timeline.audio) out_.timeline.audio.push_back(std::move(audio));
    if (block->timeline.explicit_end.value_or(0.0) >= out_.timeline.explicit_end.value_or(0.0)) {
      out_.timeline.explicit_end = block->timeline.explicit_end.value_or(0.0);
      out_.timeline.end_source = block->timeline.end_source;
    }
    for (Diagnostic& w : block->warnings) out_.warnings.push_back(std::move(w));
    for (const std::string& l : block->languages)
      if (std::find(out_.languages.begin(), out_.languages.end(), l) == out_.languages.end())
        out_.languages.push_back(l);
    for (const bml::ScheduledMark& m : block->marks) {
      marks_.emplace(std::make_pair(m.behaviour, m.id), m.time);
      mark_order_.push_back(m);
    }
    for (const bml::ScheduledBehaviour& b : block->behaviours)
      behaviours_.emplace(b.id, std::make_pair(b.start, b.end));
    return ok_status();
  }

  Status add(const xmlNode* node) {
    Pending p;
    p.node = node;
    Intention& i = p.intention;
    i.where = doc_.where(node);
    i.type = std::string(xml::local_name(node));
    i.value = std::string(xml::trim(xml::attribute(node, "type").value_or("")));
    i.id = std::string(xml::trim(xml::attribute(node, "id").value_or("")));
    Result<double> strength = read_strength(doc_, node, "importance");
    if (!strength) return strength.error();
    i.strength = *strength;
    if (!xml::attribute(node, "start"))
      return doc_.error(codes::intent::missing_attribute, node,
                        "<" + i.type + "> needs start: a time in seconds or a speech mark such as s1:tm1");
    if (!i.id.empty()) {
      const auto [it, fresh] = intention_ids_.emplace(i.id, pending_.size());
      if (!fresh)
        once_.report("duplicate " + i.id,
                     with_code(doc_.warning(node, "id",
                                            "a second intention with id '" + i.id + "' (the first is at line " +
                                                std::to_string(pending_[it->second].intention.where.line) +
                                                "): references name the first"),
                               codes::intent::duplicate_id));
    }
    pending_.push_back(std::move(p));
    return ok_status();
  }

  // The time of one attribute's reference.
  Result<double> time_of(Pending& p, const char* attribute) {
    const std::string text = xml::attribute(p.node, attribute).value_or("");
    std::string why;
    const auto ref = bml::parse_sync_ref(text, why);
    if (!ref) return doc_.error(codes::intent::bad_reference, p.node, attribute, why);
    // Beyond any animation fapc makes (--duration's bound): refused before it becomes a span whose
    // fractions a double cannot tell apart.
    if (std::abs(ref->offset) > kMaxSeconds)
      return doc_.error(codes::intent::bad_time, p.node, attribute,
                        std::string(attribute) + " '" + text + "' is beyond 10^7 seconds");
    if (ref->absolute) {
      if (ref->offset < 0)
        return doc_.error(codes::intent::bad_time, p.node, attribute,
                          std::string(attribute) + " '" + text + "' is before the document's start");
      return ref->offset;
    }
    if (const auto mark = marks_.find({ref->behaviour, ref->sync}); mark != marks_.end())
      return mark->second + ref->offset;
    const bool start = ref->sync == "start";
    if (!start && ref->sync != "end") {
      return doc_.error(codes::intent::unknown_reference, p.node, attribute,
                        "'" + text + "': no mark '" + ref->sync + "' in a speech '" + ref->behaviour + "' (" +
                            marks_of(ref->behaviour) + "), and a behaviour or intention is named by start or end");
    }
    if (const auto b = behaviours_.find(ref->behaviour); b != behaviours_.end())
      return (start ? b->second.first : b->second.second) + ref->offset;
    const auto other = intention_ids_.find(ref->behaviour);
    if (other == intention_ids_.end())
      return doc_.error(codes::intent::unknown_reference, p.node, attribute,
                        "'" + text + "': no speech, behaviour or intention '" + ref->behaviour + "'");
    Pending& named = pending_[other->second];
    if (named.state == Pending::State::resolving)
      return doc_.error(codes::intent::reference_cycle, p.node, attribute,
                        "'" + text + "' refers back to itself through a cycle of intentions");
    if (Status placed = place(named); !placed) return placed.error();
    return (start ? named.intention.start : named.intention.end) + ref->offset;
  }

  std::string marks_of(const std::string& speech) const {
    std::string out;
    int shown = 0;
    for (const bml::ScheduledMark& m : mark_order_) {
      if (m.behaviour != speech) continue;
      if (++shown > 5) return out + ", ...";
      out += (out.empty() ? "its marks are " : ", ") + m.id;
    }
    return out.empty() ? "it has no marks" : out;
  }

  // Resolves an intention's start and end (once; references to other intentions first).
  Status place(Pending& p) {
    if (p.state == Pending::State::done) return ok_status();
    p.state = Pending::State::resolving;
    Result<double> start = time_of(p, "start");
    if (!start) return start.error();
    double end = *start + kPointSpanSeconds;
    if (xml::attribute(p.node, "end")) {
      Result<double> e = time_of(p, "end");
      if (!e) return e.error();
      // Greta 0.x (SEMAINE's FML-APML) writes a duration as end: a plain end earlier than a plain
      // start is read from the start, as the BML reader reads that dialect (docs/intentions.md).
      const auto plain = [&](const char* a) {
        return bml::parse_seconds(xml::attribute(p.node, a).value_or("")).has_value();
      };
      if (*e < *start && plain("start") && plain("end")) {
        once_.report("relative end", with_code(doc_.warning(p.node, "end",
                                                            "end is earlier than start: read as a time from "
                                                            "the intention's start (Greta 0.x)"),
                                               codes::intent::time_from_start));
        *e += *start;
      }
      if (*e < *start) {
        char buffer[96];
        std::snprintf(buffer, sizeof buffer, "end (%.3f s) is before start (%.3f s)", *e, *start);
        return doc_.error(codes::intent::bad_time, p.node, "end", buffer);
      }
      if (*e > *start) end = *e;
    }
    p.intention.start = *start;
    p.intention.end = end;
    p.state = Pending::State::done;
    return ok_status();
  }
};

// Only speech text is read; elsewhere white space is dropped (as the BML reader reads).
const xml::BlankText kBlankText{false, {"text", "speech"}};

}  // namespace

Result<IntentDocument> read_fml_apml(std::string_view text, const std::string& file_name,
                                     const IntentOptions& options) {
  return read_document<FmlApmlReader>(text, file_name, options, kBlankText);
}

Result<IntentDocument> load_fml_apml(const std::string& path, const IntentOptions& options) {
  return load_document<FmlApmlReader>(path, options, kBlankText);
}

}  // namespace fapc::intent

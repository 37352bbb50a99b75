// APML (docs/intentions.md): intentions marked up over the text an agent says. The text is spoken
// (the BML reader's speech: eSpeak NG with word onsets), a <pause> splits it with a silence, and
// each element becomes intentions on the words it holds: its own (performative, theme, rheme,
// emphasis by its pitch accent, boundary as a point) and those its attributes name (affect,
// belief-relation, deictic, certainty, adjectival), drawn through the behaviour lexicon.
#include <algorithm>
#include <cctype>
#include <cmath>

#include <libxml/tree.h>

#include "bml/bml_model.hpp"
#include "bml/speak_text.hpp"
#include "fapc/intent/codes.hpp"
#include "fapc/xml/text.hpp"
#include "intent/document_reader.hpp"
#include "intent/realize.hpp"

namespace fapc::intent {
namespace {

// A place in the text: a mark of one spoken stretch (between pauses).
struct Anchor {
  std::size_t segment = 0;
  std::size_t mark = 0;
};

struct PendingIntention {
  Intention intention;
  Anchor from;
  Anchor to;
  bool point = false;  // a boundary: kPointSpanSeconds from its place
};

struct Segment {
  bml::MarkedText text;
  double silence_before = 0;
};

// Attributes that name intentions of their own, on any element.
constexpr const char* kIntentionAttributes[] = {"affect", "belief-relation", "deictic", "certainty", "adjectival"};

class ApmlReader : public DocumentReader {
 public:
  ApmlReader(const xml::XmlDocument& doc, const IntentOptions& options) : DocumentReader(doc, options, "APML") {}

  Result<IntentDocument> run() {
    Result<const xmlNode*> root = root_named("apml");
    if (!root) return root.error();
    segments_.emplace_back();
    if (Status walked = walk(*root); !walked) return walked.error();
    return finish(*root);
  }

 private:
  std::vector<Segment> segments_;
  std::vector<PendingIntention> pending_;

  Anchor mark_here() {
    bml::MarkedText& t = segments_.back().text;
    t.mark_ids.push_back(std::to_string(t.mark_ids.size()));
    t.mark_offsets.push_back(t.text.empty() ? 0 : t.text.size() + 1);
    return {segments_.size() - 1, t.mark_ids.size() - 1};
  }

  Status walk(const xmlNode* parent) {
    for (const xmlNode* n = parent->children; n != nullptr; n = n->next) {
      if (n->type == XML_TEXT_NODE || n->type == XML_CDATA_SECTION_NODE) {
        if (n->content == nullptr) continue;
        const std::string_view words = xml::trim(reinterpret_cast<const char*>(n->content));
        if (words.empty()) continue;
        std::string& text = segments_.back().text.text;
        if (!text.empty()) text += ' ';
        text += words;
        continue;
      }
      if (n->type != XML_ELEMENT_NODE) continue;
      if (Status counted = count(n, "elements"); !counted) return counted;
      const std::string name(xml::local_name(n));
      if (name == "pause") {
        if (Status paused = pause(n); !paused) return paused;
        continue;
      }
      if (Status read = element(n, name); !read) return read;
    }
    return ok_status();
  }

  Status pause(const xmlNode* n) {
    double seconds = 0;
    if (const auto sec = xml::attribute(n, "sec")) {
      const auto value = xml::decimal(xml::trim(*sec));
      if (!value || *value < 0 || *value > options_.speech.max_seconds)
        return doc_.error(codes::intent::bad_value, n, "sec",
                          "sec '" + *sec + "' is not a pause in seconds from 0 to " +
                              std::to_string(static_cast<long long>(options_.speech.max_seconds)) +
                              " (--max-speech-seconds)");
      seconds = *value;
    }
    Segment next;
    next.silence_before = seconds;
    segments_.push_back(std::move(next));
    return ok_status();
  }

  Status element(const xmlNode* n, const std::string& name) {
    std::vector<Intention> found;
    auto intention = [&](std::string type, std::string value, double strength) {
      Intention i;
      i.type = std::move(type);
      i.value = std::move(value);
      i.strength = strength;
      i.where = doc_.where(n);
      i.id = std::string(xml::trim(xml::attribute(n, "id").value_or("")));
      found.push_back(std::move(i));
    };
    std::string value(xml::trim(xml::attribute(n, "type").value_or("")));
    if (name == "emphasis") {
      value = xml::trim(xml::attribute(n, "x-pitchaccent").value_or(xml::attribute(n, "level").value_or("")));
    }
    // theme and rheme carry the information structure; their affect is the main intention.
    intention(name, value, 1.0);
    for (const char* attribute : kIntentionAttributes) {
      const auto v = xml::attribute(n, attribute);
      if (!v) continue;
      Result<double> strength =
          read_strength(doc_, n, std::string_view(attribute) == "affect" ? "intensity" : "importance");
      if (!strength) return strength.error();
      intention(attribute, std::string(xml::trim(*v)), *strength);
      found.back().where = doc_.where(n, attribute);
    }
    const Anchor from = mark_here();
    const bool point = name == "boundary";
    if (!point)
      if (Status walked = walk(n); !walked) return walked;
    const Anchor to = mark_here();
    for (Intention& i : found) pending_.push_back({std::move(i), from, to, point});
    return ok_status();
  }

  // The language the text is spoken in: the root's xml:lang (in lower case, "en-US" as the
  // engine's "en-us"), as an FML talk's lang wins over --voice; else the command line's.
  ReaderOptions speech_options(const xmlNode* root) const {
    ReaderOptions speech = options_;
    if (xmlChar* lang = xmlNodeGetLang(root)) {
      std::string language(xml::trim(reinterpret_cast<const char*>(lang)));
      xmlFree(lang);
      std::transform(language.begin(), language.end(), language.begin(),
                     [](unsigned char c) { return std::tolower(c); });
      if (!language.empty()) speech.speech.language = language;
    }
    return speech;
  }

  Result<IntentDocument> finish(const xmlNode* root) {
    const Location where = doc_.where(root);
    const ReaderOptions speech_options = this->speech_options(root);
    bml::SpeakingSoFar so_far;
    std::vector<double> begins;
    std::vector<bml::SpokenText> spoken;
    double clock = 0;
    for (Segment& s : segments_) {
      clock += s.silence_before;
      begins.push_back(clock);
      if (s.text.text.empty()) {
        bml::SpokenText silent;
        silent.mark_times.assign(s.text.mark_ids.size(), 0.0);
        spoken.push_back(std::move(silent));
        continue;
      }
      Result<bml::SpokenText> said = bml::speak(s.text, speech_options, where, out_.warnings, so_far);
      if (!said) return said.error();
      const std::string& language = speech_options.speech.language;
      if (std::find(out_.languages.begin(), out_.languages.end(), language) == out_.languages.end())
        out_.languages.push_back(language);
      // The speech is lowered as the BML reader lowers a speech behaviour.
      bml::Behaviour speech;
      speech.kind = bml::BehaviourKind::speech;
      speech.where = where;
      speech.speech = std::make_unique<bml::SpokenText>(*said);
      std::array<double, bml::kStandardPoints> t{};
      t.fill(clock);
      t[bml::kStrokeEnd] = t[bml::kRelax] = t[bml::kEnd] = clock + said->duration;
      bml::lower_behaviour(speech, t, 0, options_.speech.coarticulation, out_.timeline, out_.warnings);
      clock += said->duration;
      spoken.push_back(std::move(*said));
    }
    auto time_of = [&](const Anchor& a) { return begins[a.segment] + spoken[a.segment].mark_times[a.mark]; };
    std::vector<Intention> intentions;
    intentions.reserve(pending_.size());
    for (PendingIntention& p : pending_) {
      Intention& i = intentions.emplace_back(std::move(p.intention));
      i.start = time_of(p.from);
      i.end = p.point ? i.start + kPointSpanSeconds : std::max(time_of(p.to), i.start);
      if (i.end <= i.start) i.end = i.start + kPointSpanSeconds;
    }
    return draw_and_finish(std::move(intentions), clock, where);
  }
};

// The text is read everywhere: APML's words are the content of its elements.
const xml::BlankText kBlankText{};

}  // namespace

Result<IntentDocument> read_apml(std::string_view text, const std::string& file_name, const IntentOptions& options) {
  return read_document<ApmlReader>(text, file_name, options, kBlankText);
}

Result<IntentDocument> load_apml(const std::string& path, const IntentOptions& options) {
  return load_document<ApmlReader>(path, options, kBlankText);
}

}  // namespace fapc::intent

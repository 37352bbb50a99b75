// The SMIL-Agent reader: walks the par/seq tree (timing read as the FML reader reads it), collects
// speeches, affects and actions, speaks the speeches, schedules the tree with the one scheduler,
// places anchored affects and actions at their speech's marks and lowers everything with the BML
// reader's lowering. What it does not read is reported, once per kind, never dropped silently.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <libxml/tree.h>

#include "fapc/codec/file_io.hpp"
#include "fapc/smil/codes.hpp"
#include "fapc/smil/smil.hpp"
#include "fapc/transcoder/wav.hpp"
#include "fapc/xml/once_per_name.hpp"
#include "fapc/xml/text.hpp"
#include "fapc/xml/xml_document.hpp"
#include "fml/fml_timing.hpp"
#include "smil/agent_behaviours.hpp"
#include "smil/smil_script.hpp"

namespace fapc::smil {
namespace {

using Kind = ScheduleNode::Kind;

// The length of an unanchored affect or action without dur or end (an FML move's), and of a blink.
constexpr double kDisplaySeconds = 1.0;
constexpr double kBlinkSeconds = 0.3;
// The time an indefinite repeat is taken to fill when nothing ends it, to bound its runs (FML's).
constexpr double kUnendedSeconds = 1e6;

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

// system-language as Xface writes it (a language's English name) or as SMIL does (a code).
std::optional<std::string> language_code(std::string_view written) {
  static const std::map<std::string, std::string> kNames = {
      {"english", "en"},    {"italian", "it"}, {"french", "fr"},  {"german", "de"},  {"spanish", "es"},
      {"portuguese", "pt"}, {"dutch", "nl"},   {"swedish", "sv"}, {"finnish", "fi"}, {"greek", "el"}};
  const std::string w = lower(xml::trim(written));
  if (const auto found = kNames.find(w); found != kNames.end()) return found->second;
  const bool code = w.size() >= 2 && w.size() <= 8 && std::all_of(w.begin(), w.end(), [](char c) {
                      return std::isalpha(static_cast<unsigned char>(c)) || c == '-';
                    });
  if (code && w.find('-') != 0 && (w.size() <= 3 || w[2] == '-' || w[3] == '-')) return w;
  return std::nullopt;
}

// The attributes each element reads (docs/smil.md); others are reported once.
const std::vector<std::string_view> kCommon = {"begin",
                                               "dur",
                                               "end",
                                               "repeat",
                                               "fill",
                                               "system-language",
                                               "channel",
                                               "id",
                                               "title",
                                               "type",
                                               "system-required",
                                               "system-screen-size",
                                               "system-screen-depth"};
const std::vector<std::string_view> kSpeech = {"affect", "file"};
const std::vector<std::string_view> kAnchored = {"affect",  "content-id", "content-begin", "content-end",
                                                 "content", "intensity",  "action-type"};

class SmilReader {
 public:
  SmilReader(const xml::XmlDocument& doc, const ReaderOptions& options)
      : doc_(doc), options_(options), once_(out_.warnings) {}

  Result<SmilDocument> run() {
    const xmlNode* root = doc_.root();
    if (root == nullptr)
      return make_error(codes::smil::empty_document, Location{doc_.file(), 1, 1}, "an empty document");
    const std::string_view name = xml::local_name(root);
    if (name != "par" && name != "seq")
      return doc_.error(codes::smil::not_smil, root,
                        "the root element is <" + std::string(name) + ">, not a SMIL-Agent par or seq");
    std::optional<ScheduleNode> tree = element(root, Context{options_.speech.language});
    if (error_) return *error_;
    if (Status s = resolve_anchors(); !s) return s.error();
    if (Status s = check_speech_budget(); !s) return s.error();
    for (SmilLeaf& leaf : leaves_)
      if (leaf.kind == SmilLeaf::Kind::speech && !leaf.spoken)
        if (Status s = speak(leaf); !s) return s.error();
    set_speech_durations(*tree);
    if (Status s = check_runs(*tree); !s) return s.error();
    ScheduleOptions schedule_options;
    schedule_options.max_runs = options_.limits.max_runs;
    auto scheduled = schedule_tree(*tree, schedule_options);
    if (const auto* problem = std::get_if<ScheduleError>(&scheduled)) {
      Diagnostic d = problem->diagnostic("the element");
      if (d.source_line.empty()) d.source_line = doc_.line_text(d.where.line);
      return d;
    }
    const Schedule& schedule = std::get<Schedule>(scheduled);
    if (Status s = check_voice(schedule); !s) return s.error();
    Result<PlacedScript> placed = place_behaviours(leaves_, schedule, options_.limits.max_runs, out_.behaviours);
    if (!placed) return with_line(placed.error());
    if (options_.frames.exceeded_by(placed->end))
      return frame_budget_error(placed->end, placed->end_source, options_.frames);
    bml::lower_block(placed->block, placed->solution, 0, options_.speech.coarticulation, out_.timeline, out_.warnings);
    out_.timeline.explicit_end = placed->end;
    out_.timeline.end_source = placed->end_source;
    once_.finish();
    for (const Diagnostic& w : doc_.warnings()) out_.warnings.push_back(w);
    return std::move(out_);
  }

 private:
  struct Context {
    std::string language;
  };

  const xml::XmlDocument& doc_;
  const ReaderOptions& options_;
  SmilDocument out_;
  xml::OncePerName once_;
  std::optional<Diagnostic> error_;
  std::vector<SmilLeaf> leaves_;
  std::map<std::string, std::size_t> speeches_;  // by id
  // Anchored leaves and the node they were read from, resolved once every speech is known.
  std::vector<std::pair<std::size_t, const xmlNode*>> anchored_;
  std::map<std::size_t, std::string> said_affects_;  // speech leaf -> its own affect attribute
  std::int64_t elements_ = 0;
  bml::SpeakingSoFar spoken_so_far_;

  Diagnostic with_line(Diagnostic d) const {
    if (d.source_line.empty() && d.where.file == doc_.file()) d.source_line = doc_.line_text(d.where.line);
    return d;
  }

  bool fail(Diagnostic d) {
    if (!error_) error_ = with_line(std::move(d));
    return false;
  }

  void warn(const std::string& key, WarningCode code, Diagnostic d) {
    d.code = code.name;
    once_.report(key, std::move(d));
  }

  void check_attributes(const xmlNode* node, const std::vector<std::string_view>& own) {
    const std::string element(xml::local_name(node));
    for (const xmlAttr* attr = node->properties; attr; attr = attr->next) {
      if (attr->ns) continue;
      const std::string_view name = reinterpret_cast<const char*>(attr->name);
      if (std::find(kCommon.begin(), kCommon.end(), name) != kCommon.end()) {
        if (name.starts_with("system-") && name != "system-language")
          warn("system test " + std::string(name), codes::smil::system_test_ignored,
               doc_.warning(node, name,
                            std::string(name) + " is not tested: fapc plays the element whatever the system"));
        continue;
      }
      if (std::find(own.begin(), own.end(), name) != own.end()) continue;
      warn("attribute " + element + "@" + std::string(name), codes::smil::unknown_attribute,
           doc_.warning(
               node, name,
               "attribute '" + std::string(name) + "' of " + element + " is not part of SMIL-Agent and was ignored"));
    }
  }

  // ---- the tree --------------------------------------------------------------------------------

  std::optional<ScheduleNode> element(const xmlNode* node, Context context) {
    if (++elements_ > options_.limits.max_runs) {
      Limits limits;
      limits.max_runs = options_.limits.max_runs;
      fail(limit_error(doc_.where(node), "the script has too many elements", Limit::runs, limits));
      return std::nullopt;
    }
    if (const auto lang = xml::attribute(node, "system-language")) {
      if (const auto code = language_code(*lang)) {
        context.language = *code;
      } else {
        warn("language " + *lang, codes::smil::unknown_language,
             doc_.warning(node, "system-language",
                          "system-language '" + *lang +
                              "' is not a language fapc knows by name "
                              "(english, italian, ... or a code such as en, it): speech keeps " +
                              context.language));
      }
    }
    Result<fml::FmlTiming> timing = fml::read_fml_timing(doc_, node);
    if (!timing) {
      fail(timing.error());
      return std::nullopt;
    }
    const std::string_view name = xml::local_name(node);
    std::optional<ScheduleNode> placed;
    if (name == "par" || name == "seq") {
      check_attributes(node, {});
      xml::report_stray_text(doc_, node, once_);
      placed = ScheduleNode::group(name == "par" ? Kind::parallel : Kind::sequence, fml::group_timing(*timing),
                                   doc_.where(node));
      for (const xmlNode* child : doc_.children(node)) {
        if (std::optional<ScheduleNode> inner = element(child, context)) placed->children.push_back(std::move(*inner));
        if (error_) return std::nullopt;
      }
    } else if (name == "speech") {
      placed = speech(node, *timing, context);
    } else if (name == "speech-animation" || name == "action") {
      placed = display(node, *timing);
    } else {
      warn("element " + std::string(name), codes::smil::unknown_element,
           doc_.warning(node, "element '" + std::string(name) +
                                  "' is not part of SMIL-Agent (par, seq, speech, "
                                  "speech-animation, action) and was skipped"));
      return std::nullopt;
    }
    if (!placed || error_) return std::nullopt;
    if (!fill(node)) return std::nullopt;
    if (!repeat(node, placed->timing)) return std::nullopt;
    return placed;
  }

  // fill: freeze (and SMIL's hold) keep the end state; remove, auto and default let it go.
  bool fill(const xmlNode* node) {
    const auto text = xml::attribute(node, "fill");
    if (!text) return true;
    const std::string f = lower(xml::trim(*text));
    if (f == "freeze" || f == "hold" || f == "remove" || f == "auto" || f == "default") return true;
    return fail(doc_.error(codes::smil::bad_value, node, "fill",
                           "fill '" + *text + "' is not freeze, hold, remove, auto or default"));
  }

  bool freezes(const xmlNode* node) const {
    const std::string f = lower(xml::trim(xml::attribute(node, "fill").value_or("")));
    return f == "freeze" || f == "hold";
  }

  // repeat: a count above 0 (Xface's) or indefinite (SMIL's repeatCount).
  bool repeat(const xmlNode* node, Timing& timing) {
    const auto text = xml::attribute(node, "repeat");
    if (!text) return true;
    if (xml::trim(*text) == "indefinite") {
      timing.repeat_indefinite = true;
      return true;
    }
    const auto n = xml::decimal(xml::trim(*text));
    if (!n || *n <= 0)
      return fail(doc_.error(codes::smil::bad_value, node, "repeat",
                             "repeat '" + *text + "' is not a count above 0 or indefinite"));
    if (*n > static_cast<double>(options_.limits.max_runs)) {
      Limits limits;
      limits.max_runs = options_.limits.max_runs;
      return fail(limit_error(doc_.where(node, "repeat"), "repeat " + *text + " asks for more runs than allowed",
                              Limit::runs, limits));
    }
    timing.repeat = *n;
    return true;
  }

  std::size_t add_leaf(SmilLeaf leaf) {
    leaves_.push_back(std::move(leaf));
    return leaves_.size() - 1;
  }

  std::optional<ScheduleNode> speech(const xmlNode* node, const fml::FmlTiming& timing, const Context& context) {
    check_attributes(node, kSpeech);
    SmilLeaf leaf;
    leaf.kind = SmilLeaf::Kind::speech;
    leaf.where = doc_.where(node);
    leaf.language = context.language;
    leaf.name = xml::trim(xml::attribute(node, "id").value_or(""));
    if (!collect_text(node, leaf.text)) return std::nullopt;
    if (const auto file = xml::attribute(node, "file")) {
      if (!leaf.text.text.empty())
        warn("speech text and file", codes::smil::speech_text_ignored,
             doc_.warning(node, "file", "this speech has a recording: its text is not spoken"));
      if (!leaf.text.mark_ids.empty()) {
        fail(doc_.error(codes::smil::marks_without_words, node, "file",
                        "a speech read from a recording has no words to place its marks at"));
        return std::nullopt;
      }
      if (!record(node, *file, leaf)) return std::nullopt;
    } else if (leaf.text.text.empty()) {
      fail(doc_.error(codes::smil::empty_speech, node, "speech has no text to say and no recording (file=\"x.wav\")"));
      return std::nullopt;
    }
    if (!leaf.name.empty() && !speeches_.emplace(leaf.name, leaves_.size()).second) {
      fail(doc_.error(codes::smil::duplicate_id, node, "id", "a second speech with id '" + leaf.name + "'"));
      return std::nullopt;
    }
    out_.speeches.push_back(leaf.name);
    if (const auto affect = xml::attribute(node, "affect"))
      said_affects_[leaves_.size()] = std::string(xml::trim(*affect));
    // The duration is the speech's own, known once spoken (set_speech_durations); dur and end
    // place what follows it in a seq.
    const Timing t = fml::move_timing(timing, 0);
    if (timing.duration || timing.end) leaf.duration = t.duration;
    return ScheduleNode::leaf(add_leaf(std::move(leaf)), t, doc_.where(node));
  }

  bool collect_text(const xmlNode* node, bml::MarkedText& marked) {
    for (const xmlNode* n = node->children; n != nullptr; n = n->next) {
      if (n->type == XML_TEXT_NODE || n->type == XML_CDATA_SECTION_NODE) {
        if (n->content == nullptr) continue;
        // Xface collapses the white space of speech text: so does fapc, word by word.
        const std::string_view text = reinterpret_cast<const char*>(n->content);
        std::size_t i = 0;
        while (i < text.size()) {
          while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
          std::size_t j = i;
          while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
          if (j > i) {
            if (!marked.text.empty()) marked.text += ' ';
            marked.text += text.substr(i, j - i);
          }
          i = j;
        }
        continue;
      }
      if (n->type != XML_ELEMENT_NODE) continue;
      const std::string_view name = xml::local_name(n);
      if (name != "mark") {
        warn("in speech " + std::string(name), codes::smil::speech_markup_skipped,
             doc_.warning(n,
                          "<" + std::string(name) + "> in speech is not read (only mark is): its text is not spoken"));
        continue;
      }
      const std::string id(xml::trim(xml::attribute(n, "id").value_or("")));
      if (id.empty()) return fail(doc_.error(codes::smil::missing_attribute, n, "a mark needs an id"));
      if (std::find(marked.mark_ids.begin(), marked.mark_ids.end(), id) != marked.mark_ids.end())
        return fail(doc_.error(codes::smil::duplicate_id, n, "id", "a second mark '" + id + "' in this speech"));
      marked.mark_ids.push_back(id);
      marked.mark_offsets.push_back(marked.text.empty() ? 0 : marked.text.size() + 1);
    }
    return true;
  }

  // speech file=: a 16-bit PCM WAV, read under the include rules; its mouth does not move (a
  // recording has no phonemes), which is said once.
  bool record(const xmlNode* node, const std::string& name, SmilLeaf& leaf) {
    Result<std::string> path =
        resolve_include(xml::trim(name), doc_.file(), options_.includes, doc_.where(node, "file"));
    if (!path) return fail(path.error());
    Result<std::string> bytes = read_file_bytes(*path, options_.limits);
    if (!bytes)
      return fail(doc_.error(codes::smil::speech_file_unreadable, node, "file",
                             "speech file '" + name + "': " + bytes.error().message));
    Result<AudioClip> audio = read_wav(*bytes, *path);
    if (!audio) return fail(audio.error());
    if (static_cast<std::int64_t>(audio->samples.size()) > options_.limits.max_audio_samples)
      return fail(limit_error(doc_.where(node, "file"),
                              "speech file '" + name + "' holds " + std::to_string(audio->samples.size()) + " samples",
                              Limit::audio_samples, options_.limits));
    out_.recordings.push_back(*path);
    warn("recording", codes::smil::recording_without_visemes,
         doc_.warning(
             node, "file",
             "a recorded speech is played as it is: fapc does not find its phonemes, so the mouth does not follow it"));
    leaf.spoken = std::make_unique<bml::SpokenText>();
    audio->source = leaf.where;
    leaf.spoken->duration = static_cast<double>(audio->samples.size()) / audio->sample_rate;
    leaf.spoken->audio = std::move(*audio);
    return true;
  }

  std::optional<ScheduleNode> display(const xmlNode* node, const fml::FmlTiming& timing) {
    const bool action = xml::local_name(node) == "action";
    check_attributes(node, kAnchored);
    xml::report_stray_text(doc_, node, once_);
    SmilLeaf leaf;
    leaf.kind = action ? SmilLeaf::Kind::action : SmilLeaf::Kind::affect;
    leaf.where = doc_.where(node);
    leaf.shift = freezes(node);
    double intensity = 1;
    if (const auto text = xml::attribute(node, "intensity")) {
      const auto v = xml::decimal(xml::trim(*text));
      if (!v || *v < 0 || *v > 1) {
        fail(doc_.error(codes::smil::bad_value, node, "intensity",
                        "intensity '" + *text + "' is not a number from 0 to 1"));
        return std::nullopt;
      }
      intensity = *v;
    }
    double intrinsic = kDisplaySeconds;
    if (action && !read_action(node, intensity, leaf, intrinsic)) return std::nullopt;
    if (!action) affect(node, intensity, leaf);
    const bool anchored = xml::attribute(node, "content-id").has_value();
    Timing t = fml::move_timing(timing, intrinsic);
    if (anchored) {
      // Placed at its speech's marks, it takes no time in its container.
      leaf.offset = timing.begin.value_or(0);
      leaf.duration = timing.duration;
      if (timing.end) leaf.duration = *timing.end - leaf.offset;
      t = Timing{};
      t.duration = 0;
    } else {
      for (const char* mark : {"content-begin", "content-end"})
        if (xml::attribute(node, mark)) {
          fail(doc_.error(codes::smil::missing_attribute, node, mark,
                          std::string(mark) + " names a mark of a speech: it needs content-id, the speech"));
          return std::nullopt;
        }
    }
    const std::size_t index = add_leaf(std::move(leaf));
    if (anchored) anchored_.emplace_back(index, node);
    return ScheduleNode::leaf(index, t, doc_.where(node));
  }

  void affect(const xmlNode* node, double intensity, SmilLeaf& leaf) {
    std::optional<std::string> name = xml::attribute(node, "affect");
    if (!name) {
      // No affect of its own: the speech's (resolve_anchors), else nothing drawn.
      leaf.name = "";
      return;
    }
    set_affect(node, *name, intensity, leaf);
  }

  void set_affect(const xmlNode* node, const std::string& name, double intensity, SmilLeaf& leaf) {
    leaf.name = std::string(xml::trim(name));
    leaf.behaviours = affect_behaviours(name, intensity, leaf.shift, leaf.where);
    if (leaf.behaviours.empty())
      warn("affect " + leaf.name, codes::smil::unknown_affect,
           doc_.warning(node, xml::attribute(node, "affect") ? "affect" : "",
                        "affect '" + leaf.name +
                            "' is not in fapc's smil_affects.tsv (docs/smil.md): its span is kept, nothing is drawn"));
  }

  bool read_action(const xmlNode* node, double intensity, SmilLeaf& leaf, double& intrinsic) {
    Action action;
    action.type = xml::attribute(node, "action-type").value_or("");
    action.intensity = intensity;
    action.shift = leaf.shift;
    action.where = leaf.where;
    const std::string channel = xml::attribute(node, "channel").value_or("");
    action.channel = channel_of(channel);
    if (action.channel == Channel::other) {
      warn("channel " + channel, codes::smil::unknown_channel,
           doc_.warning(node, "channel",
                        "channel '" + channel + "' is neither the eyes nor the head: the action turns the eyes"));
      action.channel = Channel::eyes;
    }
    for (const xmlNode* child : doc_.children(node)) {
      if (xml::local_name(child) != "parameter") {
        warn("in action " + std::string(xml::local_name(child)), codes::smil::unknown_element,
             doc_.warning(
                 child, "<" + std::string(xml::local_name(child)) + "> in an action is not read (only parameter is)"));
        continue;
      }
      action.params.emplace_back(xml::trim(xml::text_content(child)));
    }
    leaf.name = action.type;
    for (const std::string& p : action.params) leaf.name += " " + p;
    std::string why;
    leaf.behaviours = action_behaviours(action, why);
    if (lower(xml::trim(action.type)).starts_with("blink")) intrinsic = kBlinkSeconds;
    if (leaf.behaviours.empty())
      warn("action " + leaf.name, codes::smil::unknown_action,
           doc_.warning(node, xml::attribute(node, "action-type") ? "action-type" : "",
                        why + ": its span is kept, nothing is drawn"));
    return true;
  }

  // content-id to its speech, content-begin and content-end to its marks; an affect without its
  // own takes the speech's.
  Status resolve_anchors() {
    for (const auto& [index, node] : anchored_) {
      SmilLeaf& leaf = leaves_[index];
      const std::string id(xml::trim(*xml::attribute(node, "content-id")));
      const auto speech = speeches_.find(id);
      if (speech == speeches_.end()) {
        std::string known;
        for (const auto& [name, i] : speeches_) known += (known.empty() ? "" : ", ") + name;
        return doc_.error(
            codes::smil::unknown_reference, node, "content-id",
            "content-id '" + id + "' names no speech of this script" +
                (known.empty() ? std::string(" (it has no speech with an id)") : " (speeches: " + known + ")"));
      }
      leaf.speech = speech->second;
      const SmilLeaf& said = leaves_[speech->second];
      for (const auto& [attribute, mark] :
           {std::pair{"content-begin", &leaf.begin_mark}, std::pair{"content-end", &leaf.end_mark}}) {
        const auto text = xml::attribute(node, attribute);
        if (!text) continue;
        const auto& ids = said.text.mark_ids;
        const auto found = std::find(ids.begin(), ids.end(), xml::trim(*text));
        if (found == ids.end())
          return doc_.error(codes::smil::unknown_reference, node, attribute,
                            std::string(attribute) + " '" + *text + "' is no mark of speech '" + id + "'");
        *mark = static_cast<std::size_t>(found - ids.begin());
      }
      if (leaf.kind == SmilLeaf::Kind::affect && !xml::attribute(node, "affect") && said_affects_.count(speech->second))
        set_affect(node, said_affects_.at(speech->second), intensity_of(node), leaf);
    }
    for (std::size_t i = 0; i < leaves_.size(); ++i)
      if (leaves_[i].kind == SmilLeaf::Kind::affect && leaves_[i].name.empty())
        warn("no affect", codes::smil::no_affect,
             with_line(make_warning(leaves_[i].where,
                                    "speech-animation without an affect, and no affect on its speech: its span is "
                                    "kept, nothing is drawn")));
    return ok_status();
  }

  static double intensity_of(const xmlNode* node) {
    const auto v = xml::decimal(xml::trim(xml::attribute(node, "intensity").value_or("1")));
    return v.value_or(1);
  }

  // ---- speech ----------------------------------------------------------------------------------

  // All speech text against the budget before any is spoken (docs/security.md).
  Status check_speech_budget() const {
    const Limits& limits = options_.limits;
    std::int64_t bytes = 0;
    double seconds = 0;
    for (const SmilLeaf& leaf : leaves_) {
      if (leaf.kind != SmilLeaf::Kind::speech || leaf.spoken) continue;
      bytes += static_cast<std::int64_t>(leaf.text.text.size());
      seconds += estimated_speech_seconds(leaf.text.text, options_.speech.words_per_minute);
      if (bytes > limits.max_speech_text_bytes)
        return with_line(limit_error(leaf.where,
                                     "the speech text of this script reaches " + std::to_string(bytes) + " bytes",
                                     Limit::speech_text, limits));
      if (seconds > limits.max_speech_seconds) {
        char shown[32];
        std::snprintf(shown, sizeof shown, "%.0f", seconds);
        return with_line(limit_error(leaf.where,
                                     std::string("the speech of this script would last at least ") + shown + " s",
                                     Limit::speech_seconds, limits));
      }
    }
    return ok_status();
  }

  Status speak(SmilLeaf& leaf) {
    ReaderOptions options = options_;
    options.speech.language = leaf.language;
    Result<bml::SpokenText> spoken = bml::speak(leaf.text, options, leaf.where, out_.warnings, spoken_so_far_);
    if (!spoken) return with_line(spoken.error());
    if (options_.speech.synthesize &&
        std::find(out_.languages.begin(), out_.languages.end(), leaf.language) == out_.languages.end())
      out_.languages.push_back(leaf.language);
    spoken->audio.source = leaf.where;
    leaf.spoken = std::make_unique<bml::SpokenText>(std::move(*spoken));
    return ok_status();
  }

  // A speech lasts as spoken unless dur or end say otherwise (its voice is not cut: they only
  // place what follows it in a seq).
  void set_speech_durations(ScheduleNode& node) {
    if (node.kind != Kind::leaf) {
      for (ScheduleNode& child : node.children) set_speech_durations(child);
      return;
    }
    const SmilLeaf& leaf = leaves_[node.leaf_id];
    if (leaf.kind == SmilLeaf::Kind::speech && !leaf.duration) node.timing.duration = leaf.spoken->duration;
  }

  // The runs the tree would make against --max-runs, before the scheduler makes them (an
  // indefinite repeat is taken to fill kUnendedSeconds when nothing ends it).
  Status check_runs(const ScheduleNode& tree) const {
    double shortest = 0;
    const double total = fml::estimated_runs(tree, kUnendedSeconds, shortest, [](std::size_t) { return 1.0; });
    if (total <= static_cast<double>(options_.limits.max_runs)) return ok_status();
    Limits limits;
    limits.max_runs = options_.limits.max_runs;
    return with_line(limit_error(tree.source, "the script repeats to too many runs", Limit::runs, limits));
  }

  // Every run of a speech places its own copy of the voice: their sum against the sample limit.
  Status check_voice(const Schedule& schedule) const {
    double samples = 0;
    for (const Occurrence& run : schedule.occurrences) {
      const SmilLeaf& leaf = leaves_[run.leaf_id];
      if (leaf.kind != SmilLeaf::Kind::speech) continue;
      samples += static_cast<double>(leaf.spoken->audio.samples.size());
      if (samples > static_cast<double>(options_.limits.max_audio_samples))
        return with_line(limit_error(leaf.where,
                                     "the voice of this speech, once per run, adds up to " +
                                         std::to_string(static_cast<std::int64_t>(samples)) + " samples",
                                     Limit::audio_samples, options_.limits));
    }
    return ok_status();
  }
};

}  // namespace

Result<SmilDocument> read_smil(std::string_view text, const std::string& file_name, const ReaderOptions& options) {
  if (const Status depth = xml::check_element_depth(text, file_name); !depth) return depth.error();
  // Only speech and parameter text is read; elsewhere white space is dropped.
  const xml::BlankText blank_text{false, {"speech", "parameter"}};
  Result<xml::XmlDocument> doc = xml::XmlDocument::parse(text, file_name, blank_text);
  if (!doc) return doc.error();
  return SmilReader(*doc, options).run();
}

Result<SmilDocument> load_smil(const std::string& path, const ReaderOptions& options) {
  const auto source = SourceText::open(path);
  if (!source) return source.error();
  return read_smil(source->bytes(), path, options);
}

}  // namespace fapc::smil

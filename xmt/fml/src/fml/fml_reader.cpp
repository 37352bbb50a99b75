// The FML reader: walks the model and the story, builds the time tree (fml_tree.hpp), schedules it
// and lowers the runs to clips. What it does not read is reported, never dropped silently.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <set>

#include <libxml/tree.h>

#include "fapc/codec/fap_table.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/nesting_limit.hpp"
#include "fapc/fml/codes.hpp"
#include "fapc/fml/fml.hpp"
#include "fapc/transcoder/audio_mix.hpp"
#include "fapc/xml/name_table.hpp"
#include "fapc/xml/once_per_name.hpp"
#include "fapc/xml/text.hpp"
#include "fapc/xml/xml_document.hpp"
#include "fml/embedded_fml.hpp"
#include "fml/fml_timing.hpp"
#include "fml/fml_tree.hpp"
#include "fml/other_formats.hpp"

namespace fapc::fml {
namespace {

using Kind = ScheduleNode::Kind;

// FAP angle units are 1e-5 rad.
constexpr double kAngleUnitsPerDegree = 1e5 * 3.14159265358979323846 / 180.0;
// The time an indefinite repeat is taken to fill when nothing ends it, to bound its runs.
constexpr double kUnendedSeconds = 1e6;

constexpr std::initializer_list<const char*> kTiming = {"begin", "duration", "dur", "end", "repeat"};

std::string trim(std::string_view s) { return std::string(xml::trim(s)); }

std::optional<double> number(std::string_view text) { return xml::decimal(xml::trim(text)); }

std::string format_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

// Event values compare as numbers when both are ("1" and "1.0"), else as text.
bool same_value(const std::string& a, const std::string& b) {
  const auto x = number(a), y = number(b);
  return x && y ? *x == *y : trim(a) == trim(b);
}

// expr types: FAP 2 expression numbers (fap_table.hpp), words of the paper and common variants.
std::optional<int> expression_number(const std::string& type) {
  static const std::map<std::string, int> kWords = {{"smile", 1},    {"joy", 1},       {"happy", 1},   {"happiness", 1},
                                                    {"sadness", 2},  {"sad", 2},       {"anger", 3},   {"angry", 3},
                                                    {"fear", 4},     {"afraid", 4},    {"disgust", 5}, {"disgusted", 5},
                                                    {"surprise", 6}, {"surprised", 6}, {"normal", 0},  {"neutral", 0}};
  if (const auto n = number(type)) {
    if (*n == std::floor(*n) && *n >= 0 && *n <= 6) return static_cast<int>(*n);
    return std::nullopt;
  }
  const auto found = kWords.find(lower(trim(type)));
  if (found == kWords.end()) return std::nullopt;
  return found->second;
}

// hdmv axes (docs/fml.md, "Moves"): 0 yaw, 1 pitch, 2 roll, as head rotation FAPs 49, 48, 50.
constexpr int kAxisFap[3] = {49, 48, 50};
std::optional<int> head_axis(const std::string& type) {
  const std::string t = lower(trim(type));
  if (t == "0" || t == "yaw") return 0;
  if (t == "1" || t == "pitch") return 1;
  if (t == "2" || t == "roll") return 2;
  return std::nullopt;
}

// The head's allowed range per axis, in degrees, from the model's range items.
struct HeadLimits {
  double min[3] = {-INFINITY, -INFINITY, -INFINITY};
  double max[3] = {INFINITY, INFINITY, INFINITY};
};

struct EventDeclaration {
  std::optional<std::string> value;  // the model's val; -1 means "not set yet"
};

class FmlReader {
 public:
  FmlReader(const xml::XmlDocument& doc, const ReaderOptions& options)
      : doc_(doc), options_(options), once_(result_.warnings) {
    profile_ = options.profile ? options.profile : &default_profile();
  }

  Result<EmbeddedFmlMove> run_embedded(const xmlNode* node) {
    const std::string name(xml::local_name(node));
    if (name != "talk" && name != "expr" && name != "hdmv" && name != "fap" && name != "param" && name != "wait") {
      return doc_.error(codes::fml::not_a_move, node,
                        "FML '" + name +
                            "' inside XMT-Omega: only FML moves (talk, expr, hdmv, fap, param, "
                            "wait) are read here; use XMT-Omega's own time containers, or "
                            "place an FML document with animation src");
    }
    std::optional<ScheduleNode> placed = element(node);
    if (error_) return *error_;
    once_.finish();
    EmbeddedFmlMove embedded;
    embedded.leaf = std::move(tree_.leaves.at(placed->leaf_id));
    if (embedded.leaf.kind == FmlLeaf::Kind::move) embedded.target = tree_.targets.at(embedded.leaf.target);
    embedded.timing = placed->timing;
    embedded.warnings = std::move(result_.warnings);
    return embedded;
  }

  // `owner`: the document itself, which the reader frees once walked.
  Result<FmlDocument> run(xml::XmlDocument* owner) {
    result_.warnings = doc_.warnings();
    const xmlNode* root = doc_.root();
    if (const std::string other = other_format_name(doc_, root); !other.empty()) {
      return doc_.error(codes::fml::other_language, root,
                        "this is " + other +
                            ", not FML (the Arya-DiPaola Face Modeling Language, "
                            "root fml with model and story): fapc does not read it");
    }
    if (xml::local_name(root) != "fml") {
      return doc_.error(
          codes::fml::not_fml, root,
          "not an FML document: the root element is '" + std::string(xml::local_name(root)) + "', expected fml");
    }
    check_attributes(root, {});
    check_text(root);
    const xmlNode* story = nullptr;
    // Streamed, the story is read where it is met (its parts freed as they are read), which is
    // the order of a parsed document's reading as long as nothing follows the story.
    bool story_read = false;
    static constexpr std::array<std::string_view, 1> kStory{"story"};
    for (const xmlNode* child : doc_.children(root, kStory)) {
      if (story_read) {
        owner->abandon_stream();
        break;
      }
      const std::string_view name = xml::local_name(child);
      if (name == "model") {
        read_model(child);
      } else if (name == "story") {
        if (story) return doc_.error(codes::fml::second_story, child, "a second story: an FML document has one");
        story = child;
        if (doc_.streamed()) {
          if (error_) return *error_;
          read_story(story);
          if (error_) return *error_;
          story_read = true;
        }
      } else {
        unknown(child, "is not part of FML (fml holds model and story) and was skipped");
      }
    }
    if (error_) return *error_;
    if (!story) return doc_.error(codes::fml::no_story, root, "fml has no story: nothing to animate");
    if (!story_read) read_story(story);
    if (error_) return *error_;
    // What follows needs no node: the tree's memory goes before the clips are made.
    templates_.clear();
    owner->release_tree();
    if (Status s = check_runs(); !s) return s.error();
    ScheduleOptions schedule_options;
    schedule_options.root_end = options_.duration;
    schedule_options.max_runs = options_.limits.max_runs;
    auto scheduled = schedule_tree(tree_.root, schedule_options);
    if (const auto* problem = std::get_if<ScheduleError>(&scheduled)) return scheduler_error(*problem);
    const Schedule& schedule = std::get<Schedule>(scheduled);
    if (options_.frames.exceeded_by(schedule.end))
      return frame_budget_error(schedule.end, story_end_source(tree_, schedule), options_.frames);
    // Lowering needs the runs and the leaves, not the tree (the root's source aside): its nodes go
    // before the clips are made.
    std::vector<ScheduleNode>().swap(tree_.root.children);
    tree_.coarticulation = options_.speech.coarticulation;
    if (Status s = check_placed_voice(schedule); !s) return s.error();
    result_.timeline = lower_fml(tree_, schedule);
    once_.finish();
    return std::move(result_);
  }

 private:
  const xml::XmlDocument& doc_;
  const ReaderOptions& options_;
  const Profile* profile_ = nullptr;
  FmlDocument result_;  // before once_, which appends to its warnings
  xml::OncePerName once_;
  std::int64_t speech_text_bytes_ = 0;  // talk text handed to the engine so far
  double speech_seconds_ = 0;           // speech it has made so far
  FmlTree tree_;
  std::optional<Diagnostic> error_;
  std::map<std::string, const xmlNode*> templates_;
  std::vector<std::string> expanding_;  // templates being expanded, outermost first
  std::map<std::string, EventDeclaration> events_;
  HeadLimits limits_;
  std::set<std::string> expressions_;
  std::string model_language_;  // the model's <character lang voice>: every talk's default
  std::string model_voice_;
  double nodes_ = 0;
  // Per node of the tree, by its ScheduleNode::tag - 1: its element name, for scheduler errors.
  std::vector<std::uint32_t> element_names_;  // in names_
  xml::NameTable names_;

  void fail(Diagnostic d) {
    if (!error_) error_ = std::move(d);
  }

  void unknown(const xmlNode* node, const std::string& why) {
    const std::string name(xml::local_name(node));
    once_.report("element " + name, doc_.warning(node, "element '" + name + "' " + why));
  }

  // Attributes other than `known` (and xml:*, xmlns) are reported once per element and attribute.
  void check_attributes(const xmlNode* element, std::initializer_list<const char*> known,
                        std::initializer_list<const char*> more = {}) {
    for (const xmlAttr* attr = element->properties; attr; attr = attr->next) {
      if (attr->ns) continue;  // xml:lang, xsi:* and other namespaced attributes carry no FML
      const std::string_view name = reinterpret_cast<const char*>(attr->name);  // as written: no prefix
      const auto listed = [&](std::initializer_list<const char*> list) {
        return std::any_of(list.begin(), list.end(), [&](const char* k) { return name == k; });
      };
      if (listed(known) || listed(more)) continue;
      const std::string element_name(xml::local_name(element));
      once_.report("attribute " + element_name + "@" + std::string(name),
                   doc_.warning(element, name,
                                "attribute '" + std::string(name) + "' of " + element_name +
                                    " is not part of FML and was ignored"));
    }
  }

  // An attribute under its paper spelling or one of its variants (docs/fml.md, "Spellings"); a
  // variant gets a note once, naming the paper's spelling.
  std::optional<std::string> spelled(const xmlNode* element, const char* paper,
                                     std::initializer_list<const char*> variants) {
    if (auto value = xml::attribute(element, paper)) return value;
    for (const char* variant : variants) {
      if (auto value = xml::attribute(element, variant)) {
        const std::string element_name(xml::local_name(element));
        once_.report(
            "variant " + element_name + "@" + variant,
            doc_.warning(element, variant, std::string(variant) + " is read as " + paper + ", the paper's spelling"));
        return value;
      }
    }
    return std::nullopt;
  }

  void check_text(const xmlNode* element) { report_stray_text(doc_, element, once_); }

  // ---- model ---------------------------------------------------------------------------------

  void read_model(const xmlNode* model) {
    check_attributes(model, {});
    check_text(model);
    for (const xmlNode* item : xml::element_children(model)) {
      const std::string_view name = xml::local_name(item);
      if (name == "character") {
        check_attributes(item, {"name", "lang", "voice"});
        result_.character = xml::attribute(item, "name").value_or("");
        model_language_ = trim(xml::attribute(item, "lang").value_or(""));
        model_voice_ = trim(xml::attribute(item, "voice").value_or(""));
      } else if (name == "img") {
        check_attributes(item, {"src", "type"});  // for the player's face model: no FAPs
      } else if (name == "param") {
        check_attributes(item, {"name", "val"});  // a player parameter (e.g. an FDP): no FAPs
      } else if (name == "range") {
        check_attributes(item, {"type", "val"}, {"dir"});
        read_range(item);
      } else if (name == "event") {
        check_attributes(item, {"name", "val"}, {"id"});
        read_event(item);
      } else if (name == "template") {
        check_attributes(item, {"name"});
        read_template(item);
      } else {
        unknown(item, "is not an FML model item and was skipped");
        continue;
      }
      if (name != "template") check_text(item);
    }
  }

  void read_range(const xmlNode* item) {
    const auto val_text = xml::attribute(item, "val");
    const auto val = val_text ? number(*val_text) : std::nullopt;
    if (!val || *val < 0) {
      fail(doc_.error(codes::fml::bad_range, item, val_text ? "val" : "",
                      "range needs val, the largest angle in degrees (>= 0)"));
      return;
    }
    // type: a direction (the paper's "left"); dir: an axis, both directions (docs/fml.md,
    // "Spellings").
    if (const auto dir = spelled(item, "type", {"dir"})) {
      const std::string d = lower(trim(*dir));
      const auto axis = head_axis(d);
      // Positive FAP directions (docs/fap-table.md section 2): yaw left, pitch down, roll right.
      if (axis) {
        limits_.min[*axis] = -*val;
        limits_.max[*axis] = *val;
      } else if (d == "left") {
        limits_.max[0] = *val;
      } else if (d == "right") {
        limits_.min[0] = -*val;
      } else if (d == "down") {
        limits_.max[1] = *val;
      } else if (d == "up") {
        limits_.min[1] = -*val;
      } else if (d == "roll-right" || d == "tilt-right") {
        limits_.max[2] = *val;
      } else if (d == "roll-left" || d == "tilt-left") {
        limits_.min[2] = -*val;
      } else {
        fail(doc_.error(codes::fml::bad_range, item, xml::attribute(item, "type") ? "type" : "dir",
                        "range type '" + *dir +
                            "' is not a direction (left, right, up, down, roll-left, "
                            "roll-right) or an axis (0 yaw, 1 pitch, 2 roll)"));
      }
      return;
    }
    fail(doc_.error(codes::fml::bad_range, item,
                    "range needs type, the direction it limits (left, right, up, down, ...)"));
  }

  void read_event(const xmlNode* item) {
    const auto name = spelled(item, "name", {"id"});
    if (!name || trim(*name).empty()) {
      fail(doc_.error(codes::fml::missing_attribute, item, "event needs name"));
      return;
    }
    if (events_.count(trim(*name))) {
      fail(doc_.error(codes::fml::declared_twice, item, "event '" + trim(*name) + "' is declared twice"));
      return;
    }
    events_[trim(*name)] = EventDeclaration{xml::attribute(item, "val")};
  }

  void read_template(const xmlNode* item) {
    const auto name = xml::attribute(item, "name");
    if (!name || trim(*name).empty()) {
      fail(doc_.error(codes::fml::missing_attribute, item, "template needs name"));
    } else if (!templates_.emplace(trim(*name), item).second) {
      fail(doc_.error(codes::fml::declared_twice, item, "name", "template '" + trim(*name) + "' is defined twice"));
    } else {
      result_.templates.push_back(trim(*name));
    }
  }

  // The value an event has for this run: --event wins over the model's val; -1 means unset.
  std::optional<std::string> event_value(const std::string& name) const {
    if (const auto given = options_.events.find(name); given != options_.events.end()) return given->second;
    const auto declared = events_.find(name);
    if (declared == events_.end() || !declared->second.value) return std::nullopt;
    if (const auto n = number(*declared->second.value); n && *n < 0) return std::nullopt;
    return declared->second.value;
  }

  void check_given_events() {
    for (const auto& [name, value] : options_.events) {
      if (!events_.count(name)) {
        result_.warnings.push_back(make_warning(codes::fml::unused_event, Location::whole_file(doc_.file()),
                                                "--event " + name + " is not declared in the model; it is unused"));
      }
    }
    for (const auto& [name, declaration] : events_) result_.events.emplace_back(name, event_value(name).value_or(""));
  }

  // ---- story ---------------------------------------------------------------------------------

  bool count_node(const xmlNode* node) {
    if (++nodes_ <= static_cast<double>(options_.limits.max_runs)) return true;
    fail(
        limit_at(doc_.error(codes::limit::runs, node, ""), "the story has too many elements after template expansion"));
    return false;
  }

  ScheduleNode remember(ScheduleNode node, const xmlNode* element) {
    element_names_.push_back(names_.number(xml::local_name(element)));
    node.tag = element_names_.size();
    return node;
  }

  void read_story(const xmlNode* story) {
    check_given_events();
    check_attributes(story, {});
    tree_.leaves.reserve(doc_.element_count());
    tree_.root = container(story, Kind::sequence, Timing{});
  }

  // A time container's children in order; excl branches and unknown elements are handled here.
  // Streamed, the containers among them are read child by child, and each child of the story is
  // freed once read (a template's, which behaviors read again, never).
  ScheduleNode container(const xmlNode* node, Kind kind, Timing timing) {
    static constexpr std::array<std::string_view, 4> kContainers{"action", "act", "seq", "par"};
    ScheduleNode group = remember(ScheduleNode::group(kind, timing, doc_.where(node)), node);
    group.children.reserve(doc_.child_count(node));  // no regrowth: a tree is ~all its nodes
    check_text(node);
    for (const xmlNode* child : doc_.children(node, kContainers, expanding_.empty())) {
      if (error_) break;
      if (auto placed = element(child)) group.children.push_back(std::move(*placed));
    }
    return group;
  }

  // repeat: a count, "indefinite", an event (loop until it is set: its value is the count, 0
  // meaning once, unset meaning indefinitely) or "event;value" (loop until it has that value).
  bool apply_repeat(const xmlNode* node, const std::optional<std::string>& repeat, Timing& timing) {
    if (!repeat) return true;
    const std::string text = trim(*repeat);
    if (text == "indefinite") {
      timing.repeat_indefinite = true;
      return true;
    }
    if (const auto n = number(text)) {
      if (*n <= 0) {
        fail(doc_.error(codes::fml::bad_repeat, node, "repeat", "repeat must be a count above 0"));
        return false;
      }
      if (*n > static_cast<double>(options_.limits.max_runs)) {
        fail(limit_at(doc_.error(codes::limit::runs, node, "repeat", ""),
                      "repeat " + text + " asks for more runs than allowed"));
        return false;
      }
      timing.repeat = *n;
      return true;
    }
    const std::size_t semicolon = text.find(';');
    const std::string event = trim(text.substr(0, semicolon));
    if (!events_.count(event)) {
      fail(doc_.error(codes::fml::bad_repeat, node, "repeat",
                      "repeat '" + text + "' is not a count, indefinite, or an event declared in the model"));
      return false;
    }
    const auto value = event_value(event);
    if (semicolon != std::string::npos) {
      const std::string until = trim(text.substr(semicolon + 1));
      timing.repeat_indefinite = !(value && same_value(*value, until));
    } else if (!value) {
      timing.repeat_indefinite = true;
    } else {
      const auto count = number(*value);
      timing.repeat = count && *count >= 1 ? std::min(*count, static_cast<double>(options_.limits.max_runs) + 1) : 1;
    }
    return true;
  }

  // Elements open around the one being read, templates expanded: a chain of templates nests as
  // deep as all of them together, and so do the schedule tree and the recursion building it.
  int depth_ = 0;

  std::optional<ScheduleNode> element(const xmlNode* node) {
    if (error_ || !count_node(node)) return std::nullopt;
    if (depth_ >= kMaxNestingDepth) {
      Diagnostic deep = nesting_too_deep(doc_.where(node), "elements (with templates expanded)");
      deep.source_line = doc_.line_text(deep.where.line);
      fail(std::move(deep));
      return std::nullopt;
    }
    ++depth_;
    std::optional<ScheduleNode> read = element_at_depth(node);
    --depth_;
    return read;
  }

  std::optional<ScheduleNode> element_at_depth(const xmlNode* node) {
    const std::string_view name = xml::local_name(node);
    Result<FmlTiming> timing = read_fml_timing(doc_, node);
    if (!timing) {
      fail(timing.error());
      return std::nullopt;
    }
    const bool group =
        name == "action" || name == "act" || name == "seq" || name == "par" || name == "excl" || name == "behavior";
    const bool move =
        name == "talk" || name == "expr" || name == "hdmv" || name == "fap" || name == "param" || name == "wait";
    if (!group && !move) {
      // Extensions of other systems (e.g. <emotion> in the published sample): their FML
      // children still play, together, as in a par.
      unknown(node, "is not part of FML; its children are read as if in a par");
      check_attributes(node, kTiming);
      Timing t = group_timing(*timing);
      if (!apply_repeat(node, timing->repeat, t)) return std::nullopt;
      return container(node, Kind::parallel, t);
    }
    std::optional<ScheduleNode> placed = group ? time_container(node, *timing) : this->move(node, *timing);
    if (!placed || error_) return std::nullopt;
    if (!apply_repeat(node, timing->repeat, placed->timing)) return std::nullopt;
    return placed;
  }

  std::optional<ScheduleNode> time_container(const xmlNode* node, const FmlTiming& timing) {
    const std::string_view name = xml::local_name(node);
    if (name == "excl") return excl(node, timing);
    if (name == "behavior") return behavior(node, timing);
    check_attributes(node, kTiming, {"ev_val", "event_value"});
    return container(node, name == "par" ? Kind::parallel : Kind::sequence, group_timing(timing));
  }

  // The branch whose ev_val is the event's value plays, alone; the others are read for errors.
  std::optional<ScheduleNode> excl(const xmlNode* node, const FmlTiming& timing) {
    check_attributes(node, kTiming, {"ev_name", "ev_id", "event_name", "ev_val", "event_value"});
    check_text(node);
    const auto event = spelled(node, "ev_name", {"ev_id", "event_name"});
    if (!event) {
      fail(doc_.error(codes::fml::missing_attribute, node, "excl needs ev_name, the event that chooses its branch"));
      return std::nullopt;
    }
    const std::string name = trim(*event);
    if (!events_.count(name) && !options_.events.count(name)) {
      fail(doc_.error(codes::fml::undeclared_event, node, xml::attribute(node, "ev_name") ? "ev_name" : "",
                      "event '" + name + "' is not declared in the model (<event name=\"" + name + "\" val=\"-1\"/>)"));
      return std::nullopt;
    }
    const auto value = event_value(name);
    ScheduleNode group = remember(ScheduleNode::group(Kind::parallel, group_timing(timing), doc_.where(node)), node);
    bool chosen = false;
    for (const xmlNode* child : xml::element_children(node)) {
      const auto branch = spelled(child, "ev_val", {"event_value"});
      if (!branch) {
        result_.warnings.push_back(
            doc_.warning(child, std::string(xml::local_name(child)) + " in excl has no ev_val: it never plays"));
      }
      std::optional<ScheduleNode> placed = element(child);
      if (error_) return std::nullopt;
      if (placed && branch && value && !chosen && same_value(*branch, *value)) {
        group.children.push_back(std::move(*placed));
        chosen = true;
      }
    }
    if (!value) {
      result_.warnings.push_back(doc_.warning(
          node, "event '" + name + "' has no value (give --event " + name + "=VALUE): the excl plays nothing"));
    } else if (!chosen) {
      result_.warnings.push_back(doc_.warning(
          node, "no branch of the excl has ev_val=\"" + *value + "\" (event '" + name + "'): it plays nothing"));
    }
    return group;
  }

  std::optional<ScheduleNode> behavior(const xmlNode* node, const FmlTiming& timing) {
    check_attributes(node, kTiming, {"name", "template", "ev_val", "event_value"});
    check_text(node);
    const auto name = spelled(node, "name", {"template"});
    if (!name) {
      fail(doc_.error(codes::fml::missing_attribute, node, "behavior needs name, the template it plays"));
      return std::nullopt;
    }
    for (const xmlNode* child : xml::element_children(node)) {
      unknown(child, "inside behavior is ignored: a behavior plays its template, which holds the content");
    }
    const std::string t = trim(*name);
    const auto found = templates_.find(t);
    if (found == templates_.end()) {
      std::string known;
      for (const auto& [n, item] : templates_) known += (known.empty() ? "" : ", ") + n;
      fail(doc_.error(codes::fml::unknown_template, node, xml::attribute(node, "name") ? "name" : "template",
                      "no template '" + t + "' in the model" + (known.empty() ? "" : " (templates: " + known + ")")));
      return std::nullopt;
    }
    if (std::find(expanding_.begin(), expanding_.end(), t) != expanding_.end()) {
      std::string chain;
      for (const std::string& e : expanding_) chain += e + " -> ";
      fail(doc_.error(codes::fml::recursive_template, node, "template '" + t + "' uses itself: " + chain + t));
      return std::nullopt;
    }
    expanding_.push_back(t);
    ScheduleNode group = container(found->second, Kind::sequence, group_timing(timing));
    expanding_.pop_back();
    group.source = doc_.where(node);
    return remember(std::move(group), node);
  }

  // ---- moves ---------------------------------------------------------------------------------

  // A move's target, its name kept once in the tree.
  std::uint32_t target_number(const std::string& name) {
    const std::uint32_t number = target_names_.number(name);
    if (number == tree_.targets.size()) tree_.targets.push_back(name);
    return number;
  }
  xml::NameTable target_names_;  // numbers of tree_.targets

  ScheduleNode add_leaf(const xmlNode* node, FmlLeaf leaf, Timing timing) {
    leaf.where = doc_.where(node);
    const std::size_t id = tree_.leaves.size();
    const Location where = leaf.where;
    tree_.leaves.push_back(std::move(leaf));
    return remember(ScheduleNode::leaf(id, timing, where), node);
  }

  // A move that cannot be animated (an unknown type) keeps its place in time as a wait.
  ScheduleNode as_wait(const xmlNode* node, const FmlTiming& timing, Diagnostic warning) {
    result_.warnings.push_back(std::move(warning));
    return add_leaf(node, FmlLeaf{}, move_timing(timing, 1.0));
  }

  static const char* value_name(const xmlNode* node) { return xml::attribute(node, "val") ? "val" : "value"; }

  std::optional<double> value_attribute(const xmlNode* node, double fallback) {
    const auto text = spelled(node, "val", {"value"});
    if (!text) return fallback;
    const auto v = number(*text);
    if (!v) fail(doc_.error(codes::fml::not_a_number, node, value_name(node), "'" + *text + "' is not a number"));
    return v;
  }

  std::optional<ScheduleNode> move(const xmlNode* node, const FmlTiming& timing) {
    const std::string_view name = xml::local_name(node);
    if (name == "talk") return talk(node, timing);
    check_text(node);
    if (name == "wait") {
      check_attributes(node, kTiming, {"ev_val", "event_value"});
      return add_leaf(node, FmlLeaf{}, move_timing(timing, 1.0));
    }
    if (name == "hdmv") {
      check_attributes(node, kTiming, {"type", "dir", "val", "value", "ev_val", "event_value"});
    } else {
      check_attributes(node, kTiming, {"type", "val", "value", "ev_val", "event_value"});
    }
    const auto type = name == "hdmv" ? spelled(node, "type", {"dir"}) : xml::attribute(node, "type");
    if (!type) {
      fail(doc_.error(codes::fml::missing_attribute, node, std::string(name) + " needs type"));
      return std::nullopt;
    }
    if (name == "expr") return expr(node, timing, *type);
    if (name == "hdmv") return hdmv(node, timing, *type);
    if (name == "fap") return fap(node, timing, *type);
    return param(node, timing, *type);
  }

  std::optional<ScheduleNode> expr(const xmlNode* node, const FmlTiming& timing, const std::string& type) {
    const auto expression = expression_number(type);
    if (!expression) {
      return as_wait(node, timing,
                     doc_.warning(node, "type",
                                  "expression type '" + type +
                                      "' is not one fapc knows (smile, sadness, anger, "
                                      "fear, disgust, surprise, normal or 0-6): it waits"));
    }
    FmlLeaf leaf;
    if (*expression == 0) {
      leaf.kind = FmlLeaf::Kind::normal;
      return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
    }
    auto percent = value_attribute(node, 100);
    if (!percent) return std::nullopt;
    if (*percent < 0 || *percent > 100) {
      result_.warnings.push_back(
          doc_.warning(node, value_name(node),
                       "expression val " + format_number(*percent) + " is outside 0-100 (%) and was clamped"));
      percent = std::clamp(*percent, 0.0, 100.0);
    }
    leaf.kind = FmlLeaf::Kind::move;
    const std::string target = "expression." + std::string(expression_name(*expression));
    leaf.target = target_number(target);
    leaf.value = *percent * 63.0 / 100.0;
    expressions_.insert(target);
    return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
  }

  std::optional<ScheduleNode> hdmv(const xmlNode* node, const FmlTiming& timing, const std::string& type) {
    const char* type_name = xml::attribute(node, "type") ? "type" : "dir";
    const auto axis = head_axis(type);
    if (!axis) {
      return as_wait(
          node, timing,
          doc_.warning(node, type_name, "head movement type '" + type + "' is not yaw, pitch, roll or 0-2: it waits"));
    }
    auto degrees = value_attribute(node, 0);
    if (!degrees) return std::nullopt;
    const double clamped = std::clamp(*degrees, limits_.min[*axis], limits_.max[*axis]);
    if (clamped != *degrees) {
      result_.warnings.push_back(doc_.warning(
          node, value_name(node),
          "head movement of " + format_number(*degrees) + " degrees is beyond the model's range and was clamped"));
    }
    FmlLeaf leaf;
    leaf.kind = FmlLeaf::Kind::move;
    leaf.target = target_number(std::string(find_fap(kAxisFap[*axis])->name));
    leaf.value = clamped * kAngleUnitsPerDegree;
    return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
  }

  std::optional<ScheduleNode> fap(const xmlNode* node, const FmlTiming& timing, const std::string& type) {
    const FapInfo* info = find_fap_by_name_or_number(trim(type));
    if (!info) {
      std::string closest;
      for (const std::string_view n : closest_fap_names(trim(type)))
        closest += (closest.empty() ? "" : ", ") + std::string(n);
      fail(doc_.error(codes::fml::bad_fap, node, "type",
                      quoted_name(type) + " is not a FAP number (3-68) or name" +
                          (closest.empty() ? std::string() : "; did you mean " + closest + "?")));
      return std::nullopt;
    }
    if (info->number < 3) {
      fail(doc_.error(codes::fml::bad_fap, node, "type",
                      "FAP " + std::to_string(info->number) +
                          " is not animated with fap: use talk (visemes) or expr (expressions)"));
      return std::nullopt;
    }
    const auto value = value_attribute(node, 0);
    if (!value) return std::nullopt;
    FmlLeaf leaf;
    leaf.kind = FmlLeaf::Kind::move;
    leaf.target = target_number(std::string(info->name));
    leaf.value = *value;
    return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
  }

  std::optional<ScheduleNode> param(const xmlNode* node, const FmlTiming& timing, const std::string& type) {
    const std::string name = trim(type);
    if (resolve_target(name, *profile_).empty() || weight_target(name)) {
      // Parameters are system-dependent (the paper's eye-wink): what the profile does not map waits.
      return as_wait(
          node, timing,
          doc_.warning(node, "type",
                       unknown_parameter_message(name, *profile_) + " (param names come from the profile): it waits"));
    }
    const auto value = value_attribute(node, 0);
    if (!value) return std::nullopt;
    FmlLeaf leaf;
    leaf.kind = FmlLeaf::Kind::move;
    leaf.target = target_number(name);
    leaf.value = *value;
    return add_leaf(node, std::move(leaf), move_timing(timing, 1.0));
  }

  std::optional<ScheduleNode> talk(const xmlNode* node, const FmlTiming& timing) {
    check_attributes(node, kTiming, {"file", "ev_val", "event_value", "lang", "voice"});
    for (const xmlNode* child : xml::element_children(node)) {
      unknown(child, "inside talk is skipped with the text in it: talk says only its own text");
    }
    const std::string text = trim(xml::text_content(node));
    const auto file = xml::attribute(node, "file");
    if (file && !text.empty()) {
      fail(doc_.error(codes::fml::talk_text_and_file, node, "file", "talk has both text and file; give one"));
      return std::nullopt;
    }
    FmlLeaf leaf;
    leaf.kind = FmlLeaf::Kind::talk;
    leaf.talk = std::make_unique<FmlTalk>();
    if (file) {
      auto speech = phonemes(node, trim(*file));
      if (!speech) return std::nullopt;
      if (speech->visemes.empty() && speech->duration == 0) {
        return as_wait(node, timing,
                       doc_.warning(node, "file",
                                    "talk file '" + *file +
                                        "' is not an MBROLA .pho "
                                        "phoneme file: fapc has no speech recogniser, so "
                                        "this talk is silent (it waits)"));
      }
      leaf.talk->speech = std::move(*speech);
    } else {
      if (text.empty()) {
        fail(doc_.error(codes::fml::talk_without_text, node,
                        "talk needs text to say or a phoneme file (file=\"x.pho\")"));
        return std::nullopt;
      }
      if (!speak(node, text, *leaf.talk)) return std::nullopt;
    }
    // The talk lasts until its sound ends and the mouth is back at neutral.
    FmlTalk& talk = *leaf.talk;
    talk.natural = talk.speech.duration;
    for (const Clip& clip : talk_timeline(talk, leaf.where, talk.speech.duration, options_.speech.coarticulation).clips)
      talk.natural = std::max(talk.natural, clip.end);
    const double intrinsic = talk.natural;
    return add_leaf(node, std::move(leaf), move_timing(timing, intrinsic));
  }

  // Talk text: spoken by the engine, or (built without one) the letter approximation, with a
  // warning once per document.
  bool speak(const xmlNode* node, const std::string& text, FmlTalk& talk) {
    if (!options_.speech.synthesize) {
      once_.report("no speech engine", doc_.warning(node,
                                                    "no speech engine (fapc built with FAPC_SPEECH=OFF, or none "
                                                    "given): talk text becomes visemes by the letter table, with "
                                                    "no voice"));
      std::string skipped;
      talk.speech = visemes_from_text(text, options_.speech.words_per_minute * 12 / 175, skipped);
      if (!skipped.empty()) {
        once_.report("skipped " + skipped, doc_.warning(node, "talk: the characters '" + skipped +
                                                                  "' have no letter-to-viseme rule and are silent"));
      }
      return true;
    }
    SpeechRequest request;
    request.text = text;
    request.language = talk_language(node);
    request.voice = xml::attribute(node, "voice") ? trim(*xml::attribute(node, "voice"))
                    : !model_voice_.empty()       ? model_voice_
                                                  : options_.speech.voice;
    request.words_per_minute = options_.speech.words_per_minute;
    request.where = xml::attribute(node, "lang") ? doc_.where(node, "lang") : doc_.where(node);
    // The document's speech budget, before the engine runs (docs/security.md): text bytes, then
    // seconds as estimated from the text; the engine then stops at the seconds left.
    const Limits& limits = options_.limits;
    speech_text_bytes_ += static_cast<std::int64_t>(text.size());
    if (speech_text_bytes_ > limits.max_speech_text_bytes) {
      fail(placed(limit_error(doc_.where(node),
                              "the talk text of this document reaches " + std::to_string(speech_text_bytes_) + " bytes",
                              Limit::speech_text, limits)));
      return false;
    }
    const double left = limits.max_speech_seconds - speech_seconds_;
    const double estimate = estimated_speech_seconds(text, request.words_per_minute);
    if (estimate > left) {
      fail(placed(limit_error(
          doc_.where(node),
          "the speech of this document would last at least " + seconds_text(speech_seconds_ + estimate) + " s",
          Limit::speech_seconds, limits)));
      return false;
    }
    request.max_seconds = std::min(left, options_.speech.max_seconds);
    Result<Utterance> spoken = options_.speech.synthesize(request);
    if (!spoken && spoken.error().kind == ErrorKind::limit_exceeded) {
      fail(placed(left <= options_.speech.max_seconds
                      ? limit_error(doc_.where(node),
                                    "the speech of this document would last more than " +
                                        seconds_text(limits.max_speech_seconds) + " s",
                                    Limit::speech_seconds, limits)
                      : make_error(codes::limit::frames, doc_.where(node),
                                   "the speech would last more than " + seconds_text(options_.speech.max_seconds) +
                                       " s (the frame limit, --max-frames, at the frame rate)")));
      return false;
    }
    if (!spoken) {
      Diagnostic refused = spoken.error();
      refused.source_line = doc_.line_text(refused.where.line);
      fail(std::move(refused));
      return false;
    }
    for (Diagnostic& warning : spoken->warnings) {
      warning.source_line = doc_.line_text(warning.where.line);
      result_.warnings.push_back(std::move(warning));
    }
    if (std::find(result_.languages.begin(), result_.languages.end(), request.language) == result_.languages.end())
      result_.languages.push_back(request.language);
    talk.speech.visemes = viseme_spans(spoken->phonemes);
    talk.speech.duration = spoken->duration;
    talk.audio = std::move(spoken->audio);
    speech_seconds_ += spoken->duration;
    return true;
  }

  // Every run of a spoken talk stores its own copy of the voice: their sum against the audio
  // sample limit, before any is made (a talk repeated 10^5 times).
  Status check_placed_voice(const Schedule& schedule) const {
    double samples = 0;
    for (const Occurrence& run : schedule.occurrences) {
      const FmlLeaf& leaf = tree_.leaves[run.leaf_id];
      if (leaf.kind != FmlLeaf::Kind::talk || run.end <= run.begin) continue;
      samples += placed_samples(leaf.talk->audio, run.begin - run.curve_offset, run.begin, run.end);
      if (samples > static_cast<double>(options_.limits.max_audio_samples))
        return placed(limit_error(leaf.where,
                                  "the voice of this talk, once per run, adds up to " +
                                      std::to_string(static_cast<std::int64_t>(samples)) + " samples",
                                  Limit::audio_samples, options_.limits));
    }
    return ok_status();
  }

  Diagnostic placed(Diagnostic d) const {
    d.source_line = doc_.line_text(d.where.line);
    return d;
  }

  static std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f", seconds);
    return text;
  }

  // The talk's `lang`, else the xml:lang in force there (on it or an ancestor), else the model's
  // character lang, else the options' (--voice).
  std::string talk_language(const xmlNode* node) const {
    if (const auto lang = xml::attribute(node, "lang")) return trim(*lang);
    if (xmlChar* inherited = xmlNodeGetLang(node)) {
      std::string lang = trim(reinterpret_cast<const char*>(inherited));
      xmlFree(inherited);
      if (!lang.empty()) return lang;
    }
    return !model_language_.empty() ? model_language_ : options_.speech.language;
  }

  // A .pho file's visemes; an empty speech for other files (the caller warns).
  std::optional<Speech> phonemes(const xmlNode* node, const std::string& name) {
    if (std::filesystem::path(name).extension() != ".pho") return Speech{};
    Result<std::string> allowed = resolve_include(name, doc_.file(), options_.includes, doc_.where(node, "file"));
    if (!allowed) {
      Diagnostic refused = allowed.error();
      refused.source_line = doc_.line_text(refused.where.line);
      fail(std::move(refused));
      return std::nullopt;
    }
    const std::string& resolved = *allowed;
    Result<std::string> text = options_.read_file ? options_.read_file(resolved) : read_file_bytes(resolved);
    if (!text) {
      fail(doc_.error(codes::fml::talk_file_unreadable, node, "file",
                      "talk file '" + name + "': " + text.error().message));
      return std::nullopt;
    }
    result_.phoneme_files.push_back(resolved);
    Result<Speech> speech = visemes_from_pho(*text, resolved, result_.warnings);
    if (!speech) {
      fail(speech.error());
      return std::nullopt;
    }
    return std::move(*speech);
  }

  // ---- scheduling ----------------------------------------------------------------------------

  // Runs the tree would make, against max_runs, before the scheduler makes them (estimated_runs,
  // fml_timing.hpp): a talk makes a run per viseme, a "normal" one per expression placed.
  double leaf_runs(std::size_t leaf_id) const {
    const FmlLeaf& leaf = tree_.leaves[leaf_id];
    return leaf.kind == FmlLeaf::Kind::talk ? std::max<double>(1, static_cast<double>(leaf.talk->speech.visemes.size()))
           : leaf.kind == FmlLeaf::Kind::normal ? std::max<double>(1, static_cast<double>(expressions_.size()))
                                                : 1;
  }

  Status check_runs() const {
    double shortest = 0;
    const double total = estimated_runs(tree_.root, options_.duration.value_or(kUnendedSeconds), shortest,
                                        [this](std::size_t leaf_id) { return leaf_runs(leaf_id); });
    if (total <= static_cast<double>(options_.limits.max_runs)) return ok_status();
    return limit_at(make_error(codes::limit::runs, tree_.root.source, ""), "the story repeats to too many runs");
  }

  // A limit_exceeded error at the place `at` points to (its source line kept).
  Diagnostic limit_at(const Diagnostic& at, const std::string& what) const {
    Limits limits;
    limits.max_runs = options_.limits.max_runs;
    Diagnostic d = limit_error(at.where, what, Limit::runs, limits);
    d.source_line = at.source_line;
    return d;
  }

  // The scheduler's problem, its subject the element it is about.
  Diagnostic scheduler_error(const ScheduleError& problem) const {
    const bool named = problem.node_tag > 0 && problem.node_tag <= element_names_.size();
    Diagnostic d =
        problem.diagnostic(named ? names_.name(element_names_[problem.node_tag - 1]) : std::string("the element"));
    if (named && problem.needs_an_end()) {
      d.message +=
          " (repeat=\"indefinite\" and unset loop events need an end: a container's duration or end, "
          "or --duration)";
    }
    if (d.where.file == doc_.file() && d.source_line.empty()) d.source_line = doc_.line_text(d.where.line);
    return d;
  }
};

// read_fml, told which parts of the text it may let go (see XmlDocument::stream).
// The document's talk text against the speech budget before it is parsed, so that no talk is
// spoken when the talks together pass it (a read streamed story is otherwise spoken talk by talk
// as it is read: 10^4 short talks took 12 s before the last ones were refused). A lexical scan
// of <talk ...>TEXT</talk> without file=, in document order: an estimate (it counts markup
// inside a talk, and talks in comments), made exact by the checks as each talk is spoken.
std::optional<Diagnostic> talk_text_over_budget(std::string_view text, const std::string& file,
                                                const ReaderOptions& options) {
  const Limits& limits = options.limits;
  std::int64_t bytes = 0;
  double seconds = 0;
  for (std::size_t at = text.find("<talk"); at != std::string_view::npos; at = text.find("<talk", at + 1)) {
    const char after = at + 5 < text.size() ? text[at + 5] : '\0';
    if (after != '>' && after != ' ' && after != '\t' && after != '\n' && after != '\r') continue;
    const std::size_t open_end = text.find('>', at);
    if (open_end == std::string_view::npos) break;
    if (text[open_end - 1] == '/' || text.substr(at, open_end - at).find("file") != std::string_view::npos) continue;
    const std::size_t close = text.find("</talk", open_end);
    if (close == std::string_view::npos) break;
    const std::string_view body = text.substr(open_end + 1, close - open_end - 1);
    bytes += static_cast<std::int64_t>(body.size());
    seconds += estimated_speech_seconds(body, options.speech.words_per_minute);
    const bool too_much_text = bytes > limits.max_speech_text_bytes;
    if (too_much_text || seconds > limits.max_speech_seconds) {
      const std::size_t line_start = text.rfind('\n', at);
      const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
      const Location where =
          Location::text(file, static_cast<int>(line),
                         static_cast<int>(at - (line_start == std::string_view::npos ? 0 : line_start + 1)) + 1);
      char shown[32];
      std::snprintf(shown, sizeof shown, "%.0f", seconds);
      return too_much_text
                 ? limit_error(where, "the talk text of this document reaches " + std::to_string(bytes) + " bytes",
                               Limit::speech_text, limits)
                 : limit_error(where, std::string("the speech of this document would last at least ") + shown + " s",
                               Limit::speech_seconds, limits);
    }
    at = close;
  }
  return std::nullopt;
}

Result<FmlDocument> read_fml_text(std::string_view text, const std::string& file_name, const ReaderOptions& options,
                                  const xml::XmlDocument::TextReleaser& release_text) {
  if (options.speech.synthesize) {
    if (auto refused = talk_text_over_budget(text, file_name, options)) return *std::move(refused);
  }
  // Only talk text is read (an FML move's, embedded or not); elsewhere white space is dropped.
  const xml::BlankText blank_text{false, {"talk"}};
  return xml::read_streamed_or_whole(text, file_name, blank_text, release_text,
                                     [&](xml::XmlDocument& doc) { return FmlReader(doc, options).run(&doc); });
}

}  // namespace

Result<EmbeddedFmlMove> read_embedded_fml_move(const xml::XmlDocument& doc, const xmlNode* move,
                                               const ReaderOptions& options) {
  return FmlReader(doc, options).run_embedded(move);
}

Result<FmlDocument> read_fml(std::string_view text, const std::string& file_name, const ReaderOptions& options) {
  return read_fml_text(text, file_name, options, {});
}

Result<FmlDocument> load_fml(const std::string& path, const ReaderOptions& options) {
  const auto source = SourceText::open(path);
  if (!source) return source.error();
  return read_fml_text(source->bytes(), path, options, [&](std::size_t offset) { source->release(offset); });
}

}  // namespace fapc::fml

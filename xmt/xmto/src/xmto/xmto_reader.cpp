// The XMT-Omega reader: walks the document, builds the time tree (xmto_tree.hpp), schedules it and
// lowers the runs to clips. What it does not read is reported, never dropped silently.
#include <algorithm>
#include <array>
#include <initializer_list>
#include <map>
#include <set>
#include <string>

#include "fapc/codec/file_io.hpp"
#include "fapc/transcoder/audio_mix.hpp"
#include "fapc/xml/name_table.hpp"
#include "fapc/xml/once_per_name.hpp"
#include "fapc/xml/xml_document.hpp"
#include "fapc/xmto/codes.hpp"
#include "fapc/xmto/xmto.hpp"
#include "fml/embedded_fml.hpp"
#include "xmto/animation_function.hpp"
#include "xmto/animation_include.hpp"
#include "xmto/attribute_target.hpp"
#include "xmto/audio_element.hpp"
#include "xmto/run_budget.hpp"
#include "xmto/smil_timing.hpp"
#include "xmto/xmto_tree.hpp"

namespace fapc::xmto {
namespace {

using Kind = ScheduleNode::Kind;

constexpr std::initializer_list<const char*> kTimingAttributes = {"begin",       "dur",       "end",
                                                                  "repeatCount", "repeatDur", "fill"};
constexpr std::string_view kXmlNamespace = "http://www.w3.org/XML/1998/namespace";
constexpr std::string_view kSchemaInstanceNamespace = "http://www.w3.org/2001/XMLSchema-instance";

class DocumentReader {
 public:
  DocumentReader(xml::XmlDocument& doc, const XmtoOptions& options)
      : doc_(doc), options_(options), once_(result_.warnings) {
    result_.warnings = doc_.warnings();
  }

  Result<XmtoDocument> run() {
    const xmlNode* root = doc_.root();
    const std::string_view name = xml::local_name(root);
    if (name == "XMT-A") {
      return doc_.error(codes::xmto::xmt_a_input, root,
                        "XMT-A input is not supported: fapc writes XMT-A (.xmt output) but reads "
                        "XMT-Omega, whose root is XMT-O");
    }
    if (name != "XMT-O") {
      return doc_.error(codes::xmto::not_xmto, root,
                        "not an XMT-Omega document: the root element is '" + std::string(name) + "', expected XMT-O");
    }
    root_namespace_ = xml::namespace_uri(root);
    check_attributes(root, {});
    const xmlNode* body = nullptr;
    // Streamed, the body is read where it is met (its parts freed as they are read), which is the
    // order of a parsed document's reading as long as nothing follows the body.
    std::optional<ScheduleNode> tree;
    bool body_read = false;
    static constexpr std::array<std::string_view, 1> kBody{"body"};
    for (const xmlNode* child : doc_.children(root, kBody)) {
      if (body_read) {
        doc_.abandon_stream();
        break;
      }
      if (!is_xmto(child)) {
        unsupported(child);
      } else if (xml::local_name(child) == "head") {
        read_head(child);
      } else if (xml::local_name(child) == "body") {
        if (body) return doc_.error(codes::xmto::second_body, child, "a second body: an XMT-O document has one");
        body = child;
        if (doc_.streamed()) {
          tree = read_body(body);
          if (error_) return *error_;
          body_read = true;
        }
      } else {
        unsupported(child);
      }
    }
    check_text(root);
    if (!body) return doc_.error(codes::xmto::no_body, root, "XMT-O has no body");
    if (!body_read) tree = read_body(body);
    if (error_) return *error_;
    // The body is a sequence (SMIL); a body that never plays leaves an empty timeline.
    tree_.root = tree ? std::move(*tree) : ScheduleNode::group(Kind::sequence, {}, doc_.where(body));
    // What follows needs no node: the tree's memory goes before the clips are made.
    doc_.release_tree();
    ScheduleOptions schedule_options;
    schedule_options.root_end = options_.duration;
    schedule_options.max_runs = options_.limits.max_runs;
    auto scheduled = schedule_tree(tree_.root, schedule_options);
    if (const auto* problem = std::get_if<ScheduleError>(&scheduled)) return scheduler_error(*problem);
    const Schedule& schedule = std::get<Schedule>(scheduled);
    if (options_.frames.exceeded_by(schedule.end))
      return frame_budget_error(schedule.end, body_end_source(tree_, schedule), options_.frames);
    // Lowering needs the runs and the leaves, not the tree (the root's source aside): its nodes go
    // before the clips are made.
    std::vector<ScheduleNode>().swap(tree_.root.children);
    if (Status s = check_placed_audio(schedule); !s) return s.error();
    result_.timeline = lower_to_timeline(tree_, schedule);
    once_.finish();
    return std::move(result_);
  }

  // Every run of an included animation or recording stores its own copy of its audio: their sum
  // against the audio sample limit, before any is made (a 10^5-fold repeatCount of a recording).
  Status check_placed_audio(const Schedule& schedule) const {
    const Limits& limits = options_.limits;
    double samples = 0;
    for (const Occurrence& run : schedule.occurrences) {
      const Leaf& leaf = tree_.leaves[run.leaf_id];
      if (!leaf.included || run.end <= run.begin) continue;
      for (const AudioClip& sound : leaf.included->audio) {
        samples += placed_samples(sound, run.begin - run.curve_offset, run.begin, run.end);
        if (samples > static_cast<double>(limits.max_audio_samples))
          return limit_error(leaf.where,
                             "the audio of this element, once per run, adds up to " +
                                 std::to_string(static_cast<std::int64_t>(samples)) + " samples",
                             Limit::audio_samples, limits);
      }
    }
    return ok_status();
  }

 private:
  xml::XmlDocument& doc_;
  const XmtoOptions& options_;
  std::string root_namespace_;
  std::optional<Diagnostic> error_;
  XmtoDocument result_;  // before once_, which appends to its warnings
  xml::OncePerName once_;
  XmtoTree tree_;
  struct ElementFacts {
    std::uint32_t name = 0;  // in names_
    bool repeats_indefinitely = false;
  };
  xml::NameTable names_;
  std::vector<ElementFacts> element_facts_;  // by ScheduleNode::tag - 1: for schedule errors
  double planned_clips_ = 0;                 // upper bound, see run_budget.hpp
  std::set<std::string> fml_expressions_;    // FAP 2 targets of the FML moves read so far

  std::optional<ScheduleNode> read_body(const xmlNode* body) {
    RunBudget budget;
    if (options_.duration) budget.available = *options_.duration;
    // Every element is at most one leaf (FML normal moves aside): no regrowth copies.
    tree_.leaves.reserve(doc_.element_count());
    // Most animations have a few values and key times (the pages never written cost nothing).
    tree_.numbers.reserve(4 * doc_.element_count());
    return element(body, Fill::remove, false, budget);
  }

  ScheduleNode scheduled_node(ScheduleNode node, const xmlNode* element) {
    element_facts_.push_back(ElementFacts{names_.number(xml::local_name(element)),
                                          node.timing.repeat_indefinite && !node.timing.repeat_duration});
    node.tag = element_facts_.size();
    return node;
  }

  void fail(Diagnostic d) {
    if (!error_) error_ = std::move(d);
  }

  // The scheduler's problem, its subject the element it is about.
  Diagnostic scheduler_error(const ScheduleError& problem) const {
    const bool named = problem.node_tag > 0 && problem.node_tag <= element_facts_.size();
    Diagnostic d =
        problem.diagnostic(named ? names_.name(element_facts_[problem.node_tag - 1].name) : std::string("the element"));
    if (named && element_facts_[problem.node_tag - 1].repeats_indefinitely)
      d.message += " (repeatCount=\"indefinite\" needs an end: from a par with dur, end, repeatDur or --duration)";
    return with_source_line(std::move(d));
  }

  Diagnostic with_source_line(Diagnostic d) const {
    if (d.where.file == doc_.file() && d.source_line.empty()) d.source_line = doc_.line_text(d.where.line);
    return d;
  }

  bool is_xmto(const xmlNode* node) const {
    const std::string_view ns = xml::namespace_uri(node);
    return ns.empty() || ns == root_namespace_ || ns == kXmtoNamespace;
  }

  // FML moves embedded in an XMT-O document ("FML documents can work as XMT-Omega code"): any
  // element whose namespace URI mentions fml. Elements share their namespace declaration, so the
  // answer for the last one seen is kept.
  // (Kept by the URI, not by the xmlNs: a streamed document frees the elements it has read, and
  // their namespace declarations with them.)
  bool is_fml(const xmlNode* node) {
    const std::string_view uri = xml::namespace_uri(node);
    if (node->ns && uri == last_ns_) return last_ns_is_fml_;
    std::string ns(uri);
    std::transform(ns.begin(), ns.end(), ns.begin(), [](unsigned char c) { return std::tolower(c); });
    last_ns_ = uri;
    last_ns_is_fml_ = ns.find("fml") != std::string::npos;
    return last_ns_is_fml_;
  }
  std::string last_ns_;
  bool last_ns_is_fml_ = false;

  void unsupported(const xmlNode* node, const std::string& why = "is not supported and was skipped") {
    std::string name(xml::local_name(node));
    if (!is_xmto(node)) name += "' in namespace '" + std::string(xml::namespace_uri(node));
    once_.report("element " + name, doc_.warning(node, "element '" + name + "' " + why));
  }

  // Attributes other than `known` (and id, xml:*, xsi:*) are reported once per element name.
  void check_attributes(const xmlNode* element, std::initializer_list<const char*> known,
                        std::initializer_list<const char*> more = {}) {
    for (const xmlAttr* attr = element->properties; attr; attr = attr->next) {
      if (attr->ns && attr->ns->href) {
        const std::string_view ns = reinterpret_cast<const char*>(attr->ns->href);
        if (ns == kXmlNamespace || ns == kSchemaInstanceNamespace) continue;
      } else if (!attr->ns || !attr->ns->prefix) {
        const std::string_view written = reinterpret_cast<const char*>(attr->name);  // no prefix
        if (written == "id") continue;
        bool listed = false;
        for (const char* k : known) listed = listed || written == k;
        for (const char* k : more) listed = listed || written == k;
        if (listed) continue;
      }
      const std::string name = xml::qualified_name(attr);
      const std::string element_name(xml::local_name(element));
      once_.report("attribute " + element_name + "@" + name,
                   doc_.warning(element, name,
                                "attribute '" + name + "' of " + element_name + " is not supported and was ignored"));
    }
  }

  // Text in XMT-O elements carries nothing for face animation, and entities are not expanded
  // (no DTD is trusted): report both rather than drop them.
  void check_text(const xmlNode* element) { report_stray_text(doc_, element, once_); }

  void read_head(const xmlNode* head) {
    check_attributes(head, {});
    check_text(head);
    for (const xmlNode* child : xml::element_children(head)) {
      if (is_xmto(child) && xml::local_name(child) == "meta") {
        check_attributes(child, {"name", "content"});
        result_.meta.emplace_back(xml::attribute(child, "name").value_or(""),
                                  xml::attribute(child, "content").value_or(""));
      } else {
        unsupported(child, "is ignored: only meta is read in head");
      }
    }
  }

  // One element of the body; empty when it contributes nothing (skipped or never plays).
  std::optional<ScheduleNode> element(const xmlNode* node, Fill inherited, bool in_excl, const RunBudget& budget) {
    if (error_) return std::nullopt;
    if (is_fml(node)) return fml_move(node, budget);
    if (!is_xmto(node)) {
      unsupported(node);
      return std::nullopt;
    }
    const std::string_view name = xml::local_name(node);
    const bool group = name == "par" || name == "seq" || name == "excl" || name == "body";
    if (!group && name != "animate" && name != "set" && name != "animation" && name != "audio") {
      unsupported(node);
      return std::nullopt;
    }
    Result<SmilTiming> timing = read_smil_timing(doc_, node);
    if (!timing) {
      fail(timing.error());
      return std::nullopt;
    }
    if (!plays(node, *timing, in_excl)) return std::nullopt;
    const Fill fill = timing->effective_fill(inherited);
    if (group) return time_container(node, *timing, fill, budget.inside(*timing, std::nullopt));
    if (name == "animation") return animation(node, *timing, fill, budget);
    if (name == "audio") return audio(node, *timing, budget);
    return animate_or_set(node, *timing, fill, budget);
  }

  bool plays(const xmlNode* node, const SmilTiming& timing, bool in_excl) {
    const std::string name(xml::local_name(node));
    if (timing.begin_indefinite) {
      result_.warnings.push_back(doc_.warning(node, "begin",
                                              name + " never plays: begin=\"indefinite\" waits "
                                                     "for an event, and fapc has none"));
      return false;
    }
    if (in_excl && !timing.has_begin()) {
      result_.warnings.push_back(doc_.warning(node, name + " in excl never plays: without begin it waits "
                                                           "for an event (SMIL); give it a begin"));
      return false;
    }
    if (timing.never_plays()) {
      result_.warnings.push_back(doc_.warning(node, "end", name + " never plays: it ends at or before its begin"));
      return false;
    }
    return true;
  }

  std::optional<ScheduleNode> time_container(const xmlNode* node, const SmilTiming& timing, Fill fill,
                                             const RunBudget& inner) {
    const std::string_view name = xml::local_name(node);
    const Kind kind = name == "par" ? Kind::parallel : name == "excl" ? Kind::exclusive : Kind::sequence;
    check_attributes(node, kTimingAttributes);
    check_text(node);
    ScheduleNode group =
        scheduled_node(ScheduleNode::group(kind, to_schedule_timing(timing, std::nullopt), doc_.where(node)), node);
    // Streamed, the containers among the children are read child by child, and each child is
    // freed once read.
    static constexpr std::array<std::string_view, 3> kContainers{"par", "seq", "excl"};
    group.children.reserve(doc_.child_count(node));  // no regrowth: a tree is ~all its nodes
    for (const xmlNode* child : doc_.children(node, kContainers, true)) {
      std::optional<ScheduleNode> placed = element(child, fill, kind == Kind::exclusive, inner);
      if (error_) return std::nullopt;
      if (placed) group.children.push_back(std::move(*placed));
    }
    return group;
  }

  // Counts the clips a leaf will make (runs times clips per run) against options_.limits.max_runs.
  bool within_budget(const xmlNode* node, double clips) {
    planned_clips_ += clips;
    if (planned_clips_ <= static_cast<double>(options_.limits.max_runs)) return true;
    const Diagnostic at = doc_.error(codes::limit::runs, node, "");
    Limits limits;
    limits.max_runs = options_.limits.max_runs;
    Diagnostic d = limit_error(
        at.where, std::string(xml::local_name(node)) + " brings the document to too many clips (repeats of repeats?)",
        Limit::runs, limits);
    d.source_line = at.source_line;
    fail(std::move(d));
    return false;
  }

  // The leaf's target and function, their names and numbers kept in the tree's pools.
  void keep_function(Leaf& leaf, const std::string& target, const AnimationFunction& function) {
    leaf.target = target_names_.number(target);
    if (leaf.target == tree_.targets.size()) tree_.targets.push_back(target);
    leaf.function = function;
    leaf.first_number = static_cast<std::uint32_t>(tree_.numbers.size());
    leaf.value_count = static_cast<std::uint32_t>(function.values.size());
    leaf.key_time_count = static_cast<std::uint32_t>(function.key_times.size());
    tree_.numbers.insert(tree_.numbers.end(), function.values.begin(), function.values.end());
    tree_.numbers.insert(tree_.numbers.end(), function.key_times.begin(), function.key_times.end());
  }
  xml::NameTable target_names_;  // numbers of tree_.targets

  ScheduleNode add_leaf(const xmlNode* node, Leaf leaf, Timing timing) {
    leaf.where = doc_.where(node);
    const std::size_t id = tree_.leaves.size();
    const Location where = leaf.where;
    tree_.leaves.push_back(std::move(leaf));
    return scheduled_node(ScheduleNode::leaf(id, timing, where), node);
  }

  std::optional<ScheduleNode> animate_or_set(const xmlNode* node, const SmilTiming& timing, Fill fill,
                                             const RunBudget& budget) {
    const bool is_set = xml::local_name(node) == "set";
    if (is_set) {
      check_attributes(node, kTimingAttributes, {"attributeName", "attributeType", "to"});
    } else {
      check_attributes(node, kTimingAttributes,
                       {"attributeName", "attributeType", "from", "to", "by", "values", "keyTimes", "calcMode",
                        "additive", "accumulate"});
    }
    check_text(node);
    Leaf leaf;
    leaf.fill = fill;
    const auto attribute_name = xml::attribute(node, "attributeName");
    if (!attribute_name) {
      fail(doc_.error(codes::xmto::missing_attribute, node,
                      std::string(xml::local_name(node)) + " needs attributeName (a FAP name or number)"));
      return std::nullopt;
    }
    std::string why;
    const auto target = resolve_attribute_name(*attribute_name, why);
    if (!target) {
      fail(doc_.error(codes::xmto::bad_target, node, "attributeName", why));
      return std::nullopt;
    }
    if (!target->warning.empty()) {
      once_.report("name " + *attribute_name, doc_.warning(node, "attributeName", target->warning));
    }
    Result<AnimationFunction> function =
        is_set ? read_set(doc_, node, timing.dur) : read_animate(doc_, node, timing.dur, result_.warnings);
    if (!function) {
      fail(function.error());
      return std::nullopt;
    }
    keep_function(leaf, target->target, *function);
    if (!within_budget(node, budget.inside(timing, std::nullopt).repeats)) return std::nullopt;
    return add_leaf(node, std::move(leaf), to_schedule_timing(timing, std::nullopt));
  }

  // An FML move: expr, hdmv, fap and param become to-animations that hold (from the value their
  // target has when they begin, so they compose with the document's other animations); normal
  // returns the expressions of the FML moves before it to 0; talk and wait are placed like an
  // included animation of their length.
  std::optional<ScheduleNode> fml_move(const xmlNode* node, const RunBudget& budget) {
    Result<fml::EmbeddedFmlMove> move = fml::read_embedded_fml_move(doc_, node, options_);
    if (!move) {
      fail(move.error());
      return std::nullopt;
    }
    result_.warnings.insert(result_.warnings.end(), move->warnings.begin(), move->warnings.end());
    const double length = move->timing.duration.value_or(0);
    const double runs = budget.repeats * (move->timing.repeat_indefinite ? budget.available / std::max(length, 1e-3)
                                                                         : move->timing.repeat);
    const auto hold = [&](const std::string& target, double value) {
      Leaf leaf;
      leaf.fill = Fill::freeze;
      AnimationFunction function;
      function.values = {0, value};
      function.to_animation = true;
      function.simple_duration = length;
      keep_function(leaf, target, function);
      return leaf;
    };
    const fml::FmlLeaf& fml = move->leaf;
    Leaf leaf;
    switch (fml.kind) {
      case fml::FmlLeaf::Kind::move:
        if (weight_target(move->target)) fml_expressions_.insert(move->target);
        if (!within_budget(node, runs)) return std::nullopt;
        return add_leaf(node, hold(move->target, fml.value), move->timing);
      case fml::FmlLeaf::Kind::normal: {
        if (!within_budget(node, runs * std::max<double>(1, static_cast<double>(fml_expressions_.size()))))
          return std::nullopt;
        ScheduleNode group = ScheduleNode::group(Kind::parallel, move->timing, doc_.where(node));
        Timing child;
        child.duration = length;
        for (const std::string& target : fml_expressions_)
          group.children.push_back(add_leaf(node, hold(target, 0), child));
        return scheduled_node(std::move(group), node);
      }
      case fml::FmlLeaf::Kind::talk:
        leaf.included = std::make_unique<Timeline>(
            fml::talk_timeline(*fml.talk, fml.where, length, options_.speech.coarticulation));
        break;
      case fml::FmlLeaf::Kind::wait:
        leaf.included = std::make_unique<Timeline>(Timeline{{}, length, doc_.where(node)});
        break;
    }
    const double clips = std::max<double>(1, static_cast<double>(leaf.included->clips.size()));
    if (!within_budget(node, runs * clips)) return std::nullopt;
    return add_leaf(node, std::move(leaf), move->timing);
  }

  std::optional<ScheduleNode> animation(const xmlNode* node, const SmilTiming& timing, Fill fill,
                                        const RunBudget& budget) {
    check_attributes(node, kTimingAttributes, {"src", "ref"});
    check_text(node);
    Result<Included> included = load_included(doc_, node, options_, result_.warnings);
    if (!included) {
      fail(with_source_line(included.error()));
      return std::nullopt;
    }
    result_.included.push_back(included->path);
    result_.warnings.insert(result_.warnings.end(), included->animation.warnings.begin(),
                            included->animation.warnings.end());
    return included_leaf(node, timing, fill, budget, std::move(included->animation.timeline));
  }

  // A leaf that plays `timeline` (an included animation, a recording) from its begin, its length
  // the timeline's; within the run budget counted in clips.
  std::optional<ScheduleNode> included_leaf(const xmlNode* node, const SmilTiming& timing, Fill fill,
                                            const RunBudget& budget, Timeline timeline) {
    const double length = timeline.end();
    const double clips_per_run = std::max<double>(1, static_cast<double>(timeline.clips.size()));
    if (!within_budget(node, budget.inside(timing, length).repeats * clips_per_run)) return std::nullopt;
    Leaf leaf;
    leaf.fill = fill;
    leaf.included = std::make_unique<Timeline>(std::move(timeline));
    return add_leaf(node, std::move(leaf), to_schedule_timing(timing, length));
  }

  // A recording (and the visemes of the .pho beside it) placed like an included animation whose
  // length is the recording's (cut by clipEnd); dur, end and repeats act on it as on any element.
  std::optional<ScheduleNode> audio(const xmlNode* node, const SmilTiming& timing, const RunBudget& budget) {
    check_attributes(node, kTimingAttributes, {"src", "clipEnd"});
    check_text(node);
    Result<Recording> recording = load_recording(doc_, node, options_, result_.warnings);
    if (!recording) {
      fail(with_source_line(recording.error()));
      return std::nullopt;
    }
    result_.included.push_back(recording->wav_path);
    if (recording->pho_path) result_.included.push_back(*recording->pho_path);
    // A recording's mouth closes when it ends, whatever the fill.
    return included_leaf(node, timing, Fill::remove, budget, std::move(recording->timeline));
  }
};

// read_xmto, told which parts of the text it may let go (see XmlDocument::stream).
Result<XmtoDocument> read_xmto_text(std::string_view text, const std::string& file_name, const XmtoOptions& options,
                                    const xml::XmlDocument::TextReleaser& release_text) {
  // Only talk text is read (an FML move's, embedded or not); elsewhere white space is dropped.
  const xml::BlankText blank_text{false, {"talk"}};
  // The reader frees the document's tree once it has walked it.
  return xml::read_streamed_or_whole(text, file_name, blank_text, release_text,
                                     [&](xml::XmlDocument& doc) { return DocumentReader(doc, options).run(); });
}

}  // namespace

Result<XmtoDocument> read_xmto(std::string_view text, const std::string& file_name, const XmtoOptions& options) {
  return read_xmto_text(text, file_name, options, {});
}

Result<XmtoDocument> load_xmto(const std::string& path, const XmtoOptions& options) {
  const auto source = SourceText::open(path);
  if (!source) return source.error();
  return read_xmto_text(source->bytes(), path, options, [&](std::size_t offset) { source->release(offset); });
}

}  // namespace fapc::xmto

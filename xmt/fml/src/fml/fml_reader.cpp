// The FML reader: walks the model and the story, builds the time tree (fml_tree.hpp), schedules it
// and lowers the runs to clips. What it does not read is reported, never dropped silently. The
// element readers are in the files fml_reader.hpp names; here are the walk, the checks every
// element reader uses, and the library's entry points.
#include <algorithm>
#include <array>

#include "fapc/codec/file_io.hpp"
#include "fml/fml_reader.hpp"
#include "fml/other_formats.hpp"

namespace fapc::fml {
namespace reading {

Result<EmbeddedFmlMove> FmlReader::run_embedded(const xmlNode* node) {
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
Result<FmlDocument> FmlReader::run(xml::XmlDocument* owner) {
  result_.warnings = doc_.warnings();
  const xmlNode* root = doc_.root();
  if (const OtherFormat other = other_format(doc_, root, options_.other_readers); !other.what.empty()) {
    return doc_.error(codes::fml::other_language, root,
                      "this is " + other.what +
                          ", not FML (the Arya-DiPaola Face Modeling Language, "
                          "root fml with model and story): " +
                          other.reading);
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

void FmlReader::fail(Diagnostic d) {
  if (!error_) error_ = std::move(d);
}

void FmlReader::unknown(const xmlNode* node, const std::string& why) {
  const std::string name(xml::local_name(node));
  once_.report("element " + name, doc_.warning(node, "element '" + name + "' " + why));
}

// Attributes other than `known` (and xml:*, xmlns) are reported once per element and attribute.
void FmlReader::check_attributes(const xmlNode* element, std::initializer_list<const char*> known,
                                 std::initializer_list<const char*> more) {
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
std::optional<std::string> FmlReader::spelled(const xmlNode* element, const char* paper,
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

}  // namespace reading

namespace {

using reading::FmlReader;
using reading::talk_text_over_budget;

// read_fml, told which parts of the text it may let go (see XmlDocument::stream).
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

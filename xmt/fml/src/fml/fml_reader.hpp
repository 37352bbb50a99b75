// The FML reader's one class, its work split by concern over the files named below (the model,
// the story's time containers, templates, repeat, the moves, talk, the limits); fml_words.hpp
// has the words FML values are written in. Private to the library: read_fml (fapc/fml/fml.hpp)
// is its door.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <libxml/tree.h>

#include "fapc/fml/codes.hpp"
#include "fapc/fml/fml.hpp"
#include "fapc/xml/name_table.hpp"
#include "fapc/xml/once_per_name.hpp"
#include "fapc/xml/text.hpp"
#include "fapc/xml/xml_document.hpp"
#include "fml/embedded_fml.hpp"
#include "fml/fml_timing.hpp"
#include "fml/fml_tree.hpp"
#include "fml/fml_words.hpp"

namespace fapc::fml::reading {

using Kind = ScheduleNode::Kind;

// The time an indefinite repeat is taken to fill when nothing ends it, to bound its runs.
inline constexpr double kUnendedSeconds = 1e6;

// The timing attributes any element of the story may carry (fml_timing.cpp reads them).
inline constexpr std::initializer_list<const char*> kTiming = {"begin", "duration", "dur", "end", "repeat"};

// The head's allowed range per axis, in degrees, from the model's range items.
struct HeadLimits {
  double min[3] = {-INFINITY, -INFINITY, -INFINITY};
  double max[3] = {INFINITY, INFINITY, INFINITY};
};

struct EventDeclaration {
  std::optional<std::string> value;  // the model's val; -1 means "not set yet"
};

// fml_limits.cpp: the document's talk text against the speech budget before it is parsed.
std::optional<Diagnostic> talk_text_over_budget(std::string_view text, const std::string& file,
                                                const ReaderOptions& options);

class FmlReader {
 public:
  FmlReader(const xml::XmlDocument& doc, const ReaderOptions& options)
      : doc_(doc), options_(options), once_(result_.warnings) {
    profile_ = options.profile ? options.profile : &default_profile();
  }

  Result<EmbeddedFmlMove> run_embedded(const xmlNode* node);
  // `owner`: the document itself, which the reader frees once walked.
  Result<FmlDocument> run(xml::XmlDocument* owner);

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
  // Elements open around the one being read, templates expanded: a chain of templates nests as
  // deep as all of them together, and so do the schedule tree and the recursion building it.
  int depth_ = 0;
  xml::NameTable target_names_;  // numbers of tree_.targets

  void check_text(const xmlNode* element) { report_stray_text(doc_, element, once_); }
  static const char* value_name(const xmlNode* node) { return xml::attribute(node, "val") ? "val" : "value"; }

  // fml_reader.cpp: what every element reader uses
  void fail(Diagnostic d);
  void unknown(const xmlNode* node, const std::string& why);
  void check_attributes(const xmlNode* element, std::initializer_list<const char*> known,
                        std::initializer_list<const char*> more = {});
  std::optional<std::string> spelled(const xmlNode* element, const char* paper,
                                     std::initializer_list<const char*> variants);

  // fml_model.cpp
  void read_model(const xmlNode* model);
  void read_range(const xmlNode* item);
  void read_event(const xmlNode* item);
  std::optional<std::string> event_value(const std::string& name) const;
  void check_given_events();

  // fml_templates.cpp
  void read_template(const xmlNode* item);
  std::optional<ScheduleNode> behavior(const xmlNode* node, const FmlTiming& timing);

  // fml_story.cpp
  void read_story(const xmlNode* story);
  ScheduleNode remember(ScheduleNode node, const xmlNode* element);
  ScheduleNode container(const xmlNode* node, Kind kind, Timing timing);
  std::optional<ScheduleNode> element(const xmlNode* node);
  std::optional<ScheduleNode> element_at_depth(const xmlNode* node);
  std::optional<ScheduleNode> time_container(const xmlNode* node, const FmlTiming& timing);
  std::optional<ScheduleNode> excl(const xmlNode* node, const FmlTiming& timing);

  // fml_repeat.cpp
  bool apply_repeat(const xmlNode* node, const std::optional<std::string>& repeat, Timing& timing);

  // fml_moves.cpp
  std::uint32_t target_number(const std::string& name);
  ScheduleNode add_leaf(const xmlNode* node, FmlLeaf leaf, Timing timing);
  ScheduleNode as_wait(const xmlNode* node, const FmlTiming& timing, Diagnostic warning);
  std::optional<double> value_attribute(const xmlNode* node, double fallback);
  std::optional<ScheduleNode> move(const xmlNode* node, const FmlTiming& timing);
  std::optional<ScheduleNode> expr(const xmlNode* node, const FmlTiming& timing, const std::string& type);
  std::optional<ScheduleNode> hdmv(const xmlNode* node, const FmlTiming& timing, const std::string& type);
  std::optional<ScheduleNode> fap(const xmlNode* node, const FmlTiming& timing, const std::string& type);
  std::optional<ScheduleNode> param(const xmlNode* node, const FmlTiming& timing, const std::string& type);

  // fml_talk.cpp
  std::optional<ScheduleNode> talk(const xmlNode* node, const FmlTiming& timing);
  bool speak(const xmlNode* node, const std::string& text, FmlTalk& talk);
  std::string talk_language(const xmlNode* node) const;
  std::optional<Speech> phonemes(const xmlNode* node, const std::string& name);

  // fml_limits.cpp
  bool count_node(const xmlNode* node);
  double leaf_runs(std::size_t leaf_id) const;
  Status check_runs() const;
  Diagnostic limit_at(const Diagnostic& at, const std::string& what) const;
  Diagnostic scheduler_error(const ScheduleError& problem) const;
  Status check_placed_voice(const Schedule& schedule) const;
  Diagnostic placed(Diagnostic d) const;
  static std::string seconds_text(double seconds);
};

}  // namespace fapc::fml::reading

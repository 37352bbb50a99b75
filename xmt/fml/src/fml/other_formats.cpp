#include "fml/other_formats.hpp"

#include <array>
#include <string_view>

#include "fml/fml_words.hpp"

namespace fapc::fml {

namespace {

constexpr const char* kNotRead = "fapc does not read it";

// The formats fapc reads come from the pipeline's table (`others`); these are the neighbours no
// reader of fapc takes, met in the Greta and MPEG-4 folders beside FML documents.
std::string unread_format_name(std::string_view root) {
  if (root == "erl") return "Greta ERL (expression library)";
  if (root == "score") return "a Greta score";
  if (root == "XMT-A") return "XMT-A";
  return {};
}

}  // namespace

OtherFormat other_format(const xml::XmlDocument& doc, const xmlNode* root, const std::vector<OtherReader>& others) {
  const std::string_view name = xml::local_name(root);
  if (name != "fml") {
    const std::string lower = reading::lower(name);
    for (const OtherReader& other : others) {
      if (other.root == lower)
        return {"a " + other.kind + " document (root <" + std::string(name) + ">)",
                "fapc reads it as " + other.extension};
    }
    return {unread_format_name(name), kNotRead};
  }
  // FML-APML's inner <fml> holds communicative intentions (performative, emotion, ...) where
  // Arya-DiPaola FML has model and story.
  static constexpr std::array<std::string_view, 1> kStory{"story"};
  for (const xmlNode* child : doc.children(root, kStory)) {
    const std::string_view c = xml::local_name(child);
    if (c == "model" || c == "story") return {};
    if (c == "performative" || c == "emotion" || c == "deictic" || c == "beat" || c == "rest" || c == "laugh" ||
        c == "world" || c == "certainty" || c == "belief-relation" || c == "other" || c == "gaze" || c == "head" ||
        c == "ideational" || c == "turnallocation" || c == "backchannel" || c == "emphasis" || c == "iconic" ||
        c == "metaphoric")
      return {"the fml part of a Greta FML-APML document", kNotRead};
  }
  return {};
}

}  // namespace fapc::fml

#include "fml/other_formats.hpp"

#include <array>
#include <string_view>

namespace fapc::xmt {

std::string other_format_name(const xml::XmlDocument& doc, const xmlNode* root) {
  const std::string_view name = xml::local_name(root);
  if (name == "fml-apml") return "Greta FML-APML";
  if (name == "apml") return "APML (Greta's Affective Presentation Markup Language)";
  if (name == "bml") return "BML (Behavior Markup Language)";
  if (name == "par" || name == "seq" || name == "smil") return "an Xface SMIL-Agent script (read it as .smil)";
  if (name == "erl") return "Greta ERL (expression library)";
  if (name == "score") return "a Greta score";
  if (name == "XMT-O") return "XMT-Omega (read it as .xmt)";
  if (name == "XMT-A") return "XMT-A";
  if (name != "fml") return {};
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
      return "the fml part of a Greta FML-APML document";
  }
  return {};
}

}  // namespace fapc::xmt

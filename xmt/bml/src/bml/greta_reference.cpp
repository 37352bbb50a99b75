#include "bml/greta_reference.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "fapc/bml/codes.hpp"
#include "fapc/xml/text.hpp"

namespace fapc::bml {
namespace {

using vocabulary::BehaviourLexicon;
using vocabulary::LexiconRow;

struct Rows {
  std::vector<const LexiconRow*> rows;
  std::vector<double> shares;
  std::string missing;  // a part of a complex expression that no row names
};

void add(Rows& out, const std::vector<const LexiconRow*>& rows, double share) {
  for (const LexiconRow* r : rows) {
    out.rows.push_back(r);
    out.shares.push_back(share);
  }
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

// CLASS=NAME through the intention lexicon: the name, then the name without its trailing number
// (Greta numbers variants of one display: fear1 ... fear4).
std::vector<const LexiconRow*> intention_rows(std::string_view intention, std::string name) {
  const BehaviourLexicon& lexicon = vocabulary::bundled_behaviour_lexicon();
  std::vector<const LexiconRow*> rows = lexicon.rows_for(intention, name);
  if (!rows.empty()) return rows;
  while (!name.empty() && std::isdigit(static_cast<unsigned char>(name.back()))) name.pop_back();
  return name.empty() ? rows : lexicon.rows_for(intention, name);
}

// complex:A_and_B shows both halves at half their amount; complex:A_maskedby_B shows the mask B
// whole and the felt A leaking through at 0.3 (docs/bml.md, "Greta references").
Rows complex_rows(std::string_view intention, std::string_view expression) {
  Rows out;
  for (const auto& [joint, first_share, second_share] :
       {std::tuple{std::string_view("_maskedby_"), 0.3, 1.0}, std::tuple{std::string_view("_and_"), 0.5, 0.5}}) {
    const std::string lowered = lower(expression);
    const std::size_t at = lowered.find(joint);
    if (at == std::string::npos) continue;
    const std::string first = lowered.substr(0, at);
    const std::string second = lowered.substr(at + joint.size());
    const auto a = intention_rows(intention, first);
    const auto b = intention_rows(intention, second);
    if (a.empty() || b.empty()) {
      out.missing = a.empty() ? first : second;
      return Rows{{}, {}, out.missing};
    }
    add(out, a, first_share);
    add(out, b, second_share);
    return out;
  }
  out.missing = std::string(expression);
  return out;
}

Rows rows_for(std::string_view element, std::string_view name) {
  Rows out;
  const std::string modality = element.starts_with("face") ? "face" : element.starts_with("gaze") ? "gaze" : "head";
  add(out, vocabulary::bundled_greta_references().rows_for(modality, name), 1.0);
  if (!out.rows.empty() || modality != "face") return out;
  const std::size_t equals = name.find('=');
  if (equals == std::string_view::npos) return out;
  const std::string_view intention = name.substr(0, equals);
  const std::string_view value = name.substr(equals + 1);
  if (value.starts_with("complex:")) return complex_rows(intention, value.substr(8));
  add(out, intention_rows(intention, std::string(value)), 1.0);
  return out;
}

// The expressivity of a gretabml description: each parameter's `.value` (or the bare name),
// -1 to 1; `.min` and `.max` bound a planner's choice and are not read.
struct Expressivity {
  double intensity = 1;
  double spc = 0, tmp = 0, fld = 0, pwr = 0, rep = 0, oac = 0;
};

}  // namespace

Result<bool> read_greta_reference(const xml::XmlDocument& doc, const xmlNode* node, Behaviour& b,
                                  xml::OncePerName& once) {
  const xmlNode* description = nullptr;
  const xmlNode* reference = nullptr;
  for (const xmlNode* child : doc.children(node))
    if (xml::local_name(child) == "description" && xml::trim(xml::attribute(child, "type").value_or("")) == "gretabml")
      description = child;
  if (description == nullptr) return false;
  for (const xmlNode* child : doc.children(description))
    if (xml::local_name(child) == "reference") reference = child;
  if (reference == nullptr) return false;
  const std::string name(xml::trim(xml::text_content(reference)));

  Expressivity e;
  for (const xmlNode* child : doc.children(description)) {
    std::string_view parameter = xml::local_name(child);
    if (parameter == "reference" || parameter.ends_with(".min") || parameter.ends_with(".max")) continue;
    if (parameter.ends_with(".value")) parameter.remove_suffix(6);
    const bool is_intensity = parameter == "intensity";
    double* slot = is_intensity         ? &e.intensity
                   : parameter == "SPC" ? &e.spc
                   : parameter == "TMP" ? &e.tmp
                   : parameter == "FLD" ? &e.fld
                   : parameter == "PWR" ? &e.pwr
                   : parameter == "REP" ? &e.rep
                   : parameter == "OAC" ? &e.oac
                                        : nullptr;
    const std::string text(xml::trim(xml::text_content(child)));
    const auto value = xml::decimal(text);
    const double low = is_intensity ? 0 : -1;
    if (slot == nullptr) {  // OPN, TEN and the like: Greta's gesture and posture qualities
      if (value && *value != 0) {
        Diagnostic w =
            doc.warning(child, "<" + std::string(xml::local_name(child)) +
                                   "> is not drawn: fapc's faces and heads have no counterpart (docs/bml.md, "
                                   "\"Greta references\")");
        w.code = codes::bml::expressivity_not_drawn.name;
        once.report("expressivity " + std::string(parameter), std::move(w));
      }
      continue;
    }
    if (!value || !std::isfinite(*value) || *value < low || *value > 1)
      return doc.error(codes::bml::bad_value, child,
                       "<" + std::string(xml::local_name(child)) + "> '" + text + "' is not a number from " +
                           (is_intensity ? "0" : "-1") + " to 1");
    *slot = *value;
  }
  // Said, not drawn: fluidity and Greta's overall activation have no counterpart in one display
  // of fixed shape; power shapes head and gaze movements only.
  const bool face = b.element.starts_with("face");
  for (const auto& [parameter, value] :
       {std::pair{"FLD", e.fld}, std::pair{"OAC", e.oac}, std::pair{"PWR", face ? e.pwr : 0.0}})
    if (value != 0) {
      Diagnostic w =
          doc.warning(description, std::string(parameter) + " is read and not drawn on a " +
                                       (face ? "face" : "head or gaze") + " (docs/bml.md, \"Greta references\")");
      w.code = codes::bml::expressivity_not_drawn.name;
      once.report("expressivity " + std::string(parameter), std::move(w));
    }

  Rows found = rows_for(b.element, name);
  if (found.rows.empty()) {
    b.kind = BehaviourKind::not_drawn;
    Diagnostic w = doc.warning(
        reference,
        "'" + name + "' is not a Greta reference fapc knows (greta_references.tsv, intentions.tsv" +
            (found.missing.empty() || found.missing == name ? std::string() : "; '" + found.missing + "' has no row") +
            "): its timing is kept, nothing is drawn");
    w.code = codes::bml::unknown_greta_name.name;
    once.report("reference " + name, std::move(w));
    return true;
  }
  b.kind = BehaviourKind::lexicon_rows;
  b.rows = std::move(found.rows);
  b.row_shares = std::move(found.shares);
  b.amount *= e.intensity * (1 + e.spc / 2) * (face ? 1 : 1 + e.pwr / 2);
  b.onset_scale = 1 - e.tmp / 2;
  b.repetition_scale = 1 + e.rep;
  return true;
}

}  // namespace fapc::bml

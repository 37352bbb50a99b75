#include "formats/xml_root.hpp"

#include <algorithm>

#include "fapc/xml/codes.hpp"

namespace fapc::pipeline {
namespace {

bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == ':' ||
         static_cast<unsigned char>(c) >= 0x80;
}

Location at(std::string_view text, std::size_t offset, const std::string& file) {
  Location where{file, 1, 1};
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++where.line;
      where.column = 1;
    } else {
      ++where.column;
    }
  }
  return where;
}

// The value of attribute `name` inside a start tag's text, if written there.
std::optional<std::string> attribute_in(std::string_view tag, std::string_view name) {
  std::size_t from = 0;
  while ((from = tag.find(name, from)) != std::string_view::npos) {
    const bool starts = from > 0 && std::isspace(static_cast<unsigned char>(tag[from - 1]));
    std::size_t i = from + name.size();
    while (i < tag.size() && std::isspace(static_cast<unsigned char>(tag[i]))) ++i;
    if (starts && i < tag.size() && tag[i] == '=') {
      ++i;
      while (i < tag.size() && std::isspace(static_cast<unsigned char>(tag[i]))) ++i;
      if (i < tag.size() && (tag[i] == '"' || tag[i] == '\'')) {
        const std::size_t close = tag.find(tag[i], i + 1);
        if (close != std::string_view::npos) return std::string(tag.substr(i + 1, close - i - 1));
      }
    }
    from += name.size();
  }
  return std::nullopt;
}

}  // namespace

Result<XmlRoot> find_xml_root(std::string_view text, const std::string& file_name) {
  std::size_t i = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  while (true) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i >= text.size() || text[i] != '<') {
      Location where = at(text, i, file_name);
      return make_error(codes::xml::no_root, where,
                        i >= text.size() ? "no root element: the text ends before any start tag"
                                         : "not XML: a start tag was expected here");
    }
    const std::string_view rest = text.substr(i);
    std::string_view close;
    if (rest.starts_with("<?"))
      close = "?>";
    else if (rest.starts_with("<!--"))
      close = "-->";
    else if (rest.starts_with("<!"))
      close = ">";  // a doctype (an internal subset ends with "]>")
    if (close.empty()) break;
    std::size_t end =
        rest.starts_with("<!DOCTYPE") && rest.find('[') < rest.find('>') ? rest.find("]>") : rest.find(close);
    if (end == std::string_view::npos)
      return make_error(codes::xml::not_well_formed, at(text, i, file_name),
                        "an unclosed declaration or comment before the root element");
    i += end + (rest.starts_with("<!DOCTYPE") && rest[end] == ']' ? 2 : close.size());
  }
  XmlRoot root;
  root.where = at(text, i, file_name);
  std::size_t j = i + 1;
  while (j < text.size() && name_char(text[j])) ++j;
  const std::string qualified(text.substr(i + 1, j - i - 1));
  if (qualified.empty())
    return make_error(codes::xml::not_well_formed, root.where, "not XML: a start tag was expected here");
  const std::size_t colon = qualified.find(':');
  root.name = colon == std::string::npos ? qualified : qualified.substr(colon + 1);
  const std::size_t tag_end = text.find('>', j);
  const std::string_view tag = text.substr(j, tag_end == std::string_view::npos ? std::string_view::npos : tag_end - j);
  const std::string ns_attribute = colon == std::string::npos ? "xmlns" : "xmlns:" + qualified.substr(0, colon);
  root.ns = attribute_in(tag, ns_attribute).value_or("");
  return root;
}

std::string lower_case(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  return name;
}

}  // namespace fapc::pipeline

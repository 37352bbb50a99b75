// Finds the start tags of an XML text and the attributes in each, by byte offset. Meant for text
// that libxml2 has already accepted as well-formed: it only has to skip what can hide a '<' (comments,
// CDATA sections, processing instructions, the DOCTYPE with its internal subset) and does not
// check anything.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapc::xml {

struct ScannedTag {
  std::size_t offset = 0;                                       // the '<'
  std::string name;                                             // qualified name as written
  std::vector<std::pair<std::string, std::size_t>> attributes;  // name as written, offset of it
  bool empty = false;                                           // an empty-element tag ("<x/>"): opens no level
};

// Start tags (and empty-element tags) in document order.
std::vector<ScannedTag> scan_start_tags(std::string_view text);

// One start tag as the scan meets it: views into the text, valid during the call only.
struct ScannedTagView {
  std::size_t offset = 0;
  std::string_view name;
  const std::vector<std::pair<std::string_view, std::size_t>>* attributes = nullptr;
  bool empty = false;
  std::size_t number = 0;  // 1-based, in document order
  std::size_t parent = 0;  // the number of the element it is in, 0 for the root
  std::size_t depth = 0;   // open elements around it, 0 for the root
};

// The same scan without a copy per tag: `on_tag` sees each start tag in document order.
void scan_start_tags(std::string_view text, const std::function<void(const ScannedTagView&)>& on_tag);

// The '<' of the first start tag nested more than `limit` elements deep, if there is one. Used
// before any parser sees the text (the scan does not recurse), so it works on any text.
std::optional<std::size_t> first_tag_deeper_than(std::string_view text, int limit);

}  // namespace fapc::xml

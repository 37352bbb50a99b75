#include "xml_tag_scan.hpp"

namespace fapc::xml {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  std::vector<ScannedTag> run() {
    std::vector<ScannedTag> tags;
    scan(
        [&tags](const ScannedTagView& tag) {
          ScannedTag copy{tag.offset, std::string(tag.name), {}, tag.empty};
          for (const auto& [name, at] : *tag.attributes) copy.attributes.emplace_back(std::string(name), at);
          tags.push_back(std::move(copy));
        },
        [] {});
    return tags;
  }

  void each(const std::function<void(const ScannedTagView&)>& on_tag) {
    scan(on_tag, [] {});
  }

  std::optional<std::size_t> first_deeper_than(int limit) {
    int depth = 0;
    std::optional<std::size_t> found;
    scan(
        [&](const ScannedTagView& tag) {
          if (tag.empty) return;
          if (++depth > limit && !found) found = tag.offset;
        },
        [&depth] { --depth; });
    return found;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::vector<std::pair<std::string_view, std::size_t>> attributes_;  // of the tag being read
  std::vector<std::size_t> open_;                                     // numbers of the elements open around the scan
  std::size_t started_ = 0;

  template <class OnStart, class OnEnd>
  void scan(OnStart on_start, OnEnd on_end) {
    while (pos_ < text_.size()) {
      if (text_[pos_] != '<') {
        ++pos_;
      } else if (starts("<!--")) {
        skip_past("-->");
      } else if (starts("<![CDATA[")) {
        skip_past("]]>");
      } else if (starts("<?")) {
        skip_past("?>");
      } else if (starts("<!")) {
        skip_declaration();
      } else if (starts("</")) {
        skip_past(">");
        if (!open_.empty()) open_.pop_back();
        on_end();
      } else {
        ScannedTagView tag = start_tag();
        tag.number = ++started_;
        tag.parent = open_.empty() ? 0 : open_.back();
        tag.depth = open_.size();
        on_start(tag);
        if (!tag.empty) open_.push_back(tag.number);
      }
    }
  }

  bool starts(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }

  void skip_past(std::string_view end) {
    const std::size_t found = text_.find(end, pos_);
    pos_ = found == std::string_view::npos ? text_.size() : found + end.size();
  }

  void skip_quoted() {
    const char quote = text_[pos_++];
    while (pos_ < text_.size() && text_[pos_] != quote) ++pos_;
    if (pos_ < text_.size()) ++pos_;
  }

  // <!DOCTYPE ... [ internal subset ]>: literals and comments inside may hold '<' and '>'.
  void skip_declaration() {
    int depth = 0;
    pos_ += 2;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '"' || c == '\'') {
        skip_quoted();
      } else if (starts("<!--")) {
        skip_past("-->");
      } else if (c == '[') {
        ++depth;
        ++pos_;
      } else if (c == ']') {
        --depth;
        ++pos_;
      } else if (c == '>' && depth <= 0) {
        ++pos_;
        return;
      } else {
        ++pos_;
      }
    }
  }

  std::string_view name() {
    const std::size_t from = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '/' && text_[pos_] != '>' &&
           text_[pos_] != '=') {
      ++pos_;
    }
    return text_.substr(from, pos_ - from);
  }

  void skip_spaces() {
    while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
  }

  ScannedTagView start_tag() {
    ScannedTagView tag;
    attributes_.clear();
    tag.attributes = &attributes_;
    tag.offset = pos_++;
    tag.name = name();
    while (true) {
      skip_spaces();
      if (pos_ >= text_.size()) break;
      if (text_[pos_] == '>') {
        ++pos_;
        break;
      }
      if (text_[pos_] == '/') {
        ++pos_;
        tag.empty = pos_ < text_.size() && text_[pos_] == '>';
        continue;
      }
      const std::size_t at = pos_;
      const std::string_view attribute = name();
      if (attribute.empty()) {  // not well-formed after all; do not loop forever
        ++pos_;
        continue;
      }
      skip_spaces();
      if (pos_ < text_.size() && text_[pos_] == '=') ++pos_;
      skip_spaces();
      if (pos_ < text_.size() && (text_[pos_] == '"' || text_[pos_] == '\'')) skip_quoted();
      attributes_.emplace_back(attribute, at);
    }
    return tag;
  }
};

}  // namespace

std::vector<ScannedTag> scan_start_tags(std::string_view text) { return Scanner(text).run(); }

void scan_start_tags(std::string_view text, const std::function<void(const ScannedTagView&)>& on_tag) {
  Scanner(text).each(on_tag);
}

std::optional<std::size_t> first_tag_deeper_than(std::string_view text, int limit) {
  return Scanner(text).first_deeper_than(limit);
}

}  // namespace fapc::xml

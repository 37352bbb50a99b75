#include "bml/sync_ref.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

namespace fapc::bml {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\n' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// BML ids are XML names without ':' (the separator of references).
bool plain_id(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
          static_cast<unsigned char>(c) >= 0x80))
      return false;
  return true;
}

}  // namespace

std::optional<double> parse_seconds(std::string_view text) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::optional<SyncRef> parse_sync_ref(std::string_view text, std::string& why) {
  text = trimmed(text);
  if (text.empty()) {
    why = "an empty sync reference";
    return std::nullopt;
  }
  SyncRef ref;
  if (const auto seconds = parse_seconds(text)) {
    ref.absolute = true;
    ref.offset = *seconds;
    return ref;
  }
  // The offset: the last '+' or '-' followed by a number (ids may hold '-', as in "s-1:end-0.5").
  std::string_view names = text;
  for (std::size_t at = text.size(); at-- > 0;) {
    if (text[at] != '+' && text[at] != '-') continue;
    if (const auto offset = parse_seconds(text.substr(at + 1));
        offset && text.substr(at + 1).find(':') == std::string_view::npos) {
      ref.offset = text[at] == '-' ? -*offset : *offset;
      names = trimmed(text.substr(0, at));
      break;
    }
  }
  std::vector<std::string_view> parts;
  std::size_t from = 0;
  for (std::size_t at = 0; at <= names.size(); ++at) {
    if (at == names.size() || names[at] == ':') {
      parts.push_back(trimmed(names.substr(from, at - from)));
      from = at + 1;
    }
  }
  if (parts.size() < 2 || parts.size() > 3) {
    why = "'" + std::string(text) + "' is not a time nor a sync reference ([block:]behaviour:syncpoint[+|-seconds])";
    return std::nullopt;
  }
  for (std::string_view part : parts)
    if (!plain_id(part)) {
      why = "'" + std::string(text) +
            "' is not a time nor a sync reference ([block:]behaviour:syncpoint[+|-seconds]): '" + std::string(part) +
            "' is not a name";
      return std::nullopt;
    }
  if (parts.size() == 3) ref.block = parts[0];
  ref.behaviour = parts[parts.size() - 2];
  ref.sync = parts.back();
  return ref;
}

std::string seconds_text(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g s", seconds);
  return buffer;
}

}  // namespace fapc::bml

#include "engine_messages.hpp"

#include <set>
#include <string>

#include "fapc/speech/codes.hpp"

namespace fapc::speech {
namespace {

constexpr std::size_t kMaxQuotedBytes = 200;

std::string quoted(std::string_view line) {
  std::string out(line.substr(0, kMaxQuotedBytes));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = ' ';
  if (line.size() > kMaxQuotedBytes) out += "...";
  return out;
}

}  // namespace

Diagnostics engine_message_warnings(std::string_view messages, std::size_t dropped, const Location& where) {
  Diagnostics out;
  std::set<std::string_view> seen;
  while (!messages.empty()) {
    const std::size_t end = messages.find('\n');
    std::string_view line = messages.substr(0, end);
    messages.remove_prefix(end == std::string_view::npos ? messages.size() : end + 1);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
    if (line.empty() || !seen.insert(line).second) continue;
    out.push_back(make_warning(
        codes::speech::engine_message, where,
        "the speech engine (eSpeak NG) reported: " + quoted(line) + " (the voice may not sound as it should)"));
  }
  if (dropped > 0)
    out.push_back(make_warning(
        codes::speech::engine_message, where,
        "the speech engine (eSpeak NG) wrote " + std::to_string(dropped) + " more bytes of messages, not shown"));
  return out;
}

}  // namespace fapc::speech

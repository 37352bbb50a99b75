// Shared by the xmto_*_test.cpp files: documents from snippets, and what the tests look at.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "fapc/transcoder/render.hpp"
#include "fapc/xmto/xmto.hpp"

namespace fapc::xmt::test {

// A whole document around `body_content` (the body's children), laid out one line per part so
// that the first child is on line 3.
inline std::string document(const std::string& body_content, const std::string& body_attributes = "") {
  return "<?xml version=\"1.0\"?>\n<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\"><body" + body_attributes + ">\n" +
         body_content + "\n</body></XMT-O>\n";
}

inline XmtoDocument read_ok(const std::string& text, const XmtoOptions& options = {}) {
  Result<XmtoDocument> read = read_xmto(text, "t.xmt", options);
  if (!read) {
    ADD_FAILURE() << "unexpected error: " << format_diagnostic(read.error());
    return {};
  }
  return std::move(*read);
}

// The error as the command line prints it (without the caret lines).
inline std::string read_error(const std::string& text, const XmtoOptions& options = {}) {
  Result<XmtoDocument> read = read_xmto(text, "t.xmt", options);
  if (read) return "no error";
  return format_diagnostic(read.error());
}

inline std::vector<std::string> messages(const Diagnostics& diagnostics) {
  std::vector<std::string> out;
  for (const Diagnostic& d : diagnostics) out.push_back(format_diagnostic(d));
  return out;
}

using Spans = std::vector<std::tuple<std::string, double, double>>;

// (target, begin, end) of every clip, in timeline order.
inline Spans spans(const Timeline& timeline) {
  Spans out;
  for (const Clip& clip : timeline.clips) out.emplace_back(clip.target, clip.begin, clip.end);
  return out;
}

inline double value_at(const Timeline& timeline, const std::string& target, double t) {
  return TimelineEvaluator(timeline).value_at(target, t);
}

}  // namespace fapc::xmt::test

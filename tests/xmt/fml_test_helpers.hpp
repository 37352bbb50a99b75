// Shared by the fml_*_test.cpp files: documents from snippets, and what the tests look at (the
// generic parts are the XMT-Omega tests').
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "fapc/fml/fml.hpp"
#include "xmto_test_helpers.hpp"

namespace fapc::fml::fml_test {

// A whole document: the model's items on line 2, the story's content from line 3 on.
inline std::string document(const std::string& story, const std::string& model = "") {
  return "<fml>\n<model>" + model + "</model>\n" + story + "\n</fml>\n";
}
inline std::string in_action(const std::string& content, const std::string& model = "") {
  return document("<story><action>" + content + "</action></story>", model);
}

inline FmlDocument read_ok(const std::string& text, const ReaderOptions& options = {}) {
  Result<FmlDocument> read = read_fml(text, "t.fml", options);
  if (!read) {
    ADD_FAILURE() << "unexpected error: " << format_diagnostic(read.error());
    return {};
  }
  return std::move(*read);
}

inline std::string read_error(const std::string& text, const ReaderOptions& options = {}) {
  Result<FmlDocument> read = read_fml(text, "t.fml", options);
  return read ? "no error" : format_diagnostic(read.error());
}

using xmto::test::messages;
using xmto::test::Spans;
using xmto::test::spans;

// Spans equal to within 1e-9 s (times like 5/12 s are not exact in binary).
inline void expect_spans(const Timeline& timeline, const Spans& expected) {
  const Spans actual = spans(timeline);
  ASSERT_EQ(actual.size(), expected.size()) << ::testing::PrintToString(actual);
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(std::get<0>(actual[i]), std::get<0>(expected[i])) << i;
    EXPECT_NEAR(std::get<1>(actual[i]), std::get<1>(expected[i]), 1e-9) << i;
    EXPECT_NEAR(std::get<2>(actual[i]), std::get<2>(expected[i]), 1e-9) << i;
  }
}

// Key points of a clip's curve as (time, value).
inline std::vector<std::pair<double, double>> keys(const Clip& clip) {
  std::vector<std::pair<double, double>> out;
  for (const KeyPoint& k : clip.curve.keys) out.emplace_back(k.time, k.value);
  return out;
}

}  // namespace fapc::fml::fml_test

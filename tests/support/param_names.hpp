// Test names for suites whose parameter is a file path (the corpus tests): its letters and
// digits, anything else as '_', and the index, since two paths may differ only in punctuation.
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <string>

namespace fapc::test {

inline std::string identifier(const std::string& text) {
  std::string name;
  for (char c : text) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

inline std::string file_param_name(const testing::TestParamInfo<std::string>& p) {
  return identifier(p.param) + "_" + std::to_string(p.index);
}

}  // namespace fapc::test

// The FML reader names the reader a document of another format goes to from the table's rows
// (their xml_roots, handed down in ReaderOptions::other_readers), not from a list of its own: a
// row added with a root is named without touching the FML reader.
#include <gtest/gtest.h>

#include <string>

#include "fapc/fml/codes.hpp"
#include "fapc/fml/fml.hpp"
#include "fapc/pipeline/registry.hpp"
#include "reader_options.hpp"

namespace fapc {
namespace {

TEST(FmlNamesOtherReaders, EveryRowWithARootIsNamedWithItsExtension) {
  const ReaderOptions options = pipeline::reader_options(pipeline::ConvertOptions{});
  int named = 0;
  for (const pipeline::InputFormat& f : pipeline::formats().inputs()) {
    for (const std::string& root : f.xml_roots) {
      if (root == "fml") continue;  // the reader's own
      const auto read = fml::read_fml("<" + root + "/>\n", "x.fml", options);
      ASSERT_FALSE(read.ok()) << root;
      const std::string expected = "this is a " + f.kind + " document (root <" + root + ">), not FML";
      EXPECT_EQ(read.error().message.substr(0, expected.size()), expected) << read.error().message;
      EXPECT_TRUE(read.error().message.ends_with("fapc reads it as " + f.extensions.front())) << read.error().message;
      EXPECT_EQ(read.error().code, codes::fml::other_language.name);
      ++named;
    }
  }
  EXPECT_GE(named, 5);  // fml-apml, apml, bml, smil's par and seq, xmt-o
}

}  // namespace
}  // namespace fapc

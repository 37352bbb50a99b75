// The schema registry of the xml library writes the XMT namespaces itself, so that validation
// depends on neither the XMT-A writer nor the XMT-Omega reader; they must still agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "fapc/mpeg4/xmta_writer.hpp"
#include "fapc/xml/xml_validation.hpp"
#include "fapc/xmto/xmto.hpp"

namespace fapc::xml {
namespace {

bool validates_kind(const std::string& expected) {
  const std::vector<std::string> kinds = validated_document_kinds();
  return std::find(kinds.begin(), kinds.end(), expected) != kinds.end();
}

TEST(SchemaNamespaces, AgreeWithTheWriterAndTheReader) {
  EXPECT_TRUE(validates_kind("XMT-A (" + std::string(mpeg4::kXmtaNamespace) + ")"));
  EXPECT_TRUE(validates_kind("XMT-Omega (" + std::string(xmto::kXmtoNamespace) + ")"));
}

}  // namespace
}  // namespace fapc::xml

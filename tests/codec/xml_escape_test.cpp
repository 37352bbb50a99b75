// The one escaping of the XML and HTML fapc writes; expectations written by hand from XML 1.0
// sections 2.4 (markup characters) and 3.3.3 (attribute-value normalisation).
#include <gtest/gtest.h>

#include "fapc/codec/xml_escape.hpp"

namespace fapc {
namespace {

TEST(XmlEscape, MarkupCharactersBecomeEntitiesEverywhere) {
  EXPECT_EQ(xml_escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c'");
  EXPECT_EQ(xml_escape("a<b>&\"c'", XmlPlace::attribute), "a&lt;b&gt;&amp;&quot;c'");
}

TEST(XmlEscape, LineEndsAndTabsStayInTextButNotInAttributes) {
  EXPECT_EQ(xml_escape("1\r\n2\t3"), "1\r\n2\t3");
  EXPECT_EQ(xml_escape("1\r\n2\t3", XmlPlace::attribute), "1&#13;&#10;2&#9;3");
}

TEST(XmlEscape, OtherBytesPassThrough) {
  EXPECT_EQ(xml_escape("Ω é 0x7f\x7f"), "Ω é 0x7f\x7f");
  EXPECT_EQ(xml_escape(""), "");
}

}  // namespace
}  // namespace fapc

// eSpeak NG's own messages (transcoder/speech/src/engine_messages.hpp): never printed by fapc's
// libraries, each distinct one a warning at the talk with code speech.engine_message.
#include <gtest/gtest.h>

#include "engine_messages.hpp"
#include "fapc/speech/engine.hpp"
#include "support/captured_stderr.hpp"

namespace fapc {
namespace {

TEST(EngineMessages, OneWarningPerDistinctLineAtThePlace) {
  const Location at = Location::text("talk.fml", 4, 9);
  const Diagnostics out =
      speech::engine_message_warnings("espeak: No envelope\nespeak: No envelope\r\n\nBad \x01intonation data\n", 0, at);
  ASSERT_EQ(out.size(), 2u);
  for (const Diagnostic& d : out) {
    EXPECT_EQ(d.severity, Severity::warning);
    EXPECT_EQ(d.code, "speech.engine_message");
    EXPECT_EQ(d.where.line, 4);
    EXPECT_EQ(d.where.column, 9);
  }
  EXPECT_NE(out[0].message.find("reported: espeak: No envelope ("), std::string::npos) << out[0].message;
  EXPECT_NE(out[1].message.find("reported: Bad  intonation data ("), std::string::npos) << out[1].message;
}

TEST(EngineMessages, LongLinesAndDroppedBytesStayBounded) {
  const Diagnostics out = speech::engine_message_warnings(std::string(5000, 'z'), 123, Location{});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_LT(out[0].message.size(), 300u);
  EXPECT_NE(out[1].message.find("123 more bytes"), std::string::npos) << out[1].message;
}

// Belarusian's dictionary is a stub in espeak-ng-data 1.51: loading the voice makes the engine
// print "Full dictionary is not installed for 'be'".
TEST(EngineMessages, TheEnginesOwnMessageBecomesAWarningNotAPrint) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  SpeechRequest request;
  request.text = "Прывітанне";
  request.language = "be";
  request.where = Location::text("be.fml", 2, 3);
  test::CapturedStderr captured;
  const Result<Utterance> spoken = speech::engine()(request);
  const std::string printed = captured.take();
  ASSERT_TRUE(spoken) << format_diagnostic(spoken.error());
  EXPECT_EQ(printed, "");
  bool reported = false;
  for (const Diagnostic& d : spoken->warnings)
    if (d.code == "speech.engine_message" &&
        d.message.find("Full dictionary is not installed for 'be'") != std::string::npos)
      reported = d.where.line == 2 && d.where.column == 3;
  EXPECT_TRUE(reported) << "no placed warning for the engine's message";
  EXPECT_FALSE(spoken->audio.samples.empty());
}

}  // namespace
}  // namespace fapc

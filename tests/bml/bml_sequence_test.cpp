// Several BML blocks given in order (docs/bml.md, "Several blocks"): each block placed by its
// composition (MERGE when sent, APPEND after every earlier block, REPLACE when sent, cutting what
// still runs), measured on the behaviours' start and end times and on the clips; references to
// earlier blocks; the list's errors placed at its line and column, the documents' in the document.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fapc/bml/bml.hpp"
#include "fapc/speech/engine.hpp"
#include "support/test_support.hpp"

namespace fapc::bml {
namespace {

namespace fs = std::filesystem;

// A face display lasts 2 s by itself, a nod of one repetition 0.9 s (docs/bml.md, "Defaults").
constexpr double kFace = 2.0;
constexpr double kNod = 0.9;

std::string folder() { return test::scratch_folder("bml-sequence"); }

void write(const std::string& name, const std::string& text) {
  std::ofstream(fs::path(folder()) / name, std::ios::binary) << text;
}

std::string block(const std::string& id, const std::string& composition, const std::string& body) {
  return "<bml xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\" id=\"" + id + "\"" +
         (composition.empty() ? "" : " composition=\"" + composition + "\"") + ">\n" + body + "\n</bml>\n";
}

Result<BmlDocument> read_list(const std::string& list) {
  const std::string path = (fs::path(folder()) / "list.bmlseq").string();
  std::ofstream(path, std::ios::binary) << list;
  return load_bml_sequence(path);
}

BmlDocument read_ok(const std::string& list) {
  Result<BmlDocument> d = read_list(list);
  EXPECT_TRUE(d) << (d ? "" : format_diagnostic(d.error()));
  return d ? std::move(*d) : BmlDocument{};
}

const ScheduledBehaviour* find(const BmlDocument& d, const std::string& block, const std::string& id) {
  for (const ScheduledBehaviour& b : d.behaviours)
    if (b.block == block && b.id == id) return &b;
  return nullptr;
}

const ScheduledBehaviour& behaviour(const BmlDocument& d, const std::string& block, const std::string& id) {
  if (const ScheduledBehaviour* b = find(d, block, id)) return *b;
  static const ScheduledBehaviour none;
  ADD_FAILURE() << "no behaviour " << block << ":" << id;
  return none;
}

TEST(BmlSequence, MergeStartsAlongsideAppendAfterEverything) {
  write("a.bml", block("a", "", R"(<faceLexeme id="smile" lexeme="RAISE_MOUTH_CORNERS"/>)"));
  write("b.bml", block("b", "APPEND", R"(<head id="nod" lexeme="NOD"/>)"));
  write("c.bml", block("c", "MERGE", R"(<head id="nod" lexeme="NOD" start="0.5"/>)"));
  const BmlDocument d = read_ok("a.bml\nb.bml\nc.bml\n");
  EXPECT_EQ(d.blocks, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(d.compositions, (std::vector<std::string>{"MERGE", "APPEND", "MERGE"}));
  // All three are sent at 0: b waits for a's end; c merges with what runs at 0 (a), its nod
  // 0.5 s into it.
  EXPECT_EQ(d.block_starts, (std::vector<double>{0, kFace, 0}));
  EXPECT_DOUBLE_EQ(behaviour(d, "b", "nod").start, kFace);
  EXPECT_DOUBLE_EQ(behaviour(d, "b", "nod").end, kFace + kNod);
  EXPECT_DOUBLE_EQ(behaviour(d, "c", "nod").start, 0.5);
  // The clips are where the behaviours are: b's nod turns the head from 2 s on.
  bool b_nod = false;
  for (const Clip& c : d.timeline.clips)
    if (c.target == "head_pitch" && c.begin == kFace) b_nod = c.end == kFace + kNod;
  EXPECT_TRUE(b_nod);
  EXPECT_DOUBLE_EQ(d.timeline.end(), kFace + kNod);
}

TEST(BmlSequence, AppendWaitsForTheLatestEndNotTheLastBlock) {
  write("long.bml", block("long", "", R"(<faceLexeme id="f" lexeme="RAISE_BROWS" end="5"/>)"));
  write("short.bml", block("short", "MERGE", R"(<head id="nod" lexeme="NOD"/>)"));
  write("after.bml", block("after", "APPEND", R"(<head id="nod" lexeme="NOD"/>)"));
  const BmlDocument d = read_ok("long.bml\nshort.bml\nafter.bml\n");
  EXPECT_DOUBLE_EQ(behaviour(d, "after", "nod").start, 5);
}

TEST(BmlSequence, ReplaceCutsWhatRunsAndDropsWhatHadNotStarted) {
  write("a.bml", block("a", "", R"(<faceLexeme id="smile" lexeme="RAISE_MOUTH_CORNERS" start="0" end="4"/>
<head id="late" lexeme="NOD" start="3"/>)"));
  write("r.bml", block("r", "REPLACE", R"(<head id="shake" lexeme="SHAKE"/>)"));
  const BmlDocument d = read_ok("a.bml\nat 1.5 r.bml\n");
  EXPECT_EQ(d.block_starts, (std::vector<double>{0, 1.5}));
  EXPECT_DOUBLE_EQ(behaviour(d, "a", "smile").end, 1.5);
  EXPECT_EQ(find(d, "a", "late"), nullptr);  // it would have started at 3
  EXPECT_DOUBLE_EQ(behaviour(d, "r", "shake").start, 1.5);
  for (const Clip& c : d.timeline.clips) {
    if (c.source.file.str().ends_with("a.bml")) {
      EXPECT_LE(c.end, 1.5) << c.target.str();
      EXPECT_EQ(c.fill, Fill::remove);
    }
    EXPECT_NE(c.target.str(), "head_pitch") << "the removed nod is drawn";
  }
  ASSERT_FALSE(d.warnings.empty());
  EXPECT_EQ(d.warnings.back().code, "bml.replaced");
  EXPECT_EQ(d.warnings.back().where.line, 1);
}

TEST(BmlSequence, ReplaceStopsTheVoice) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  write(
      "talk.bml",
      block("talk", "", R"(<speech id="s"><text>This sentence takes well over half a second to say.</text></speech>)"));
  write("stop.bml", block("stop", "REPLACE", R"(<head id="nod" lexeme="NOD"/>)"));
  const std::string path = (fs::path(folder()) / "voice.bmlseq").string();
  std::ofstream(path, std::ios::binary) << "talk.bml\nat 0.5 stop.bml\n";
  ReaderOptions options;
  options.speech.synthesize = speech::engine();
  Result<BmlDocument> d = load_bml_sequence(path, options);
  ASSERT_TRUE(d) << format_diagnostic(d.error());
  ASSERT_EQ(d->timeline.audio.size(), 1U);
  const AudioClip& voice = d->timeline.audio.front();
  EXPECT_EQ(voice.samples.size(), static_cast<std::size_t>(0.5 * voice.sample_rate));
  EXPECT_DOUBLE_EQ(behaviour(*d, "talk", "s").end, 0.5);
}

TEST(BmlSequence, ReplaceKeepsAFinishedShiftsHeldState) {
  write("a.bml", block("a", "", R"(<faceShift id="s" lexeme="RAISE_BROWS"/>)"));
  write("r.bml", block("r", "REPLACE", R"(<head id="nod" lexeme="NOD"/>)"));
  const BmlDocument d = read_ok("a.bml\nat 1 r.bml\n");
  bool held = false;
  for (const Clip& c : d.timeline.clips)
    if (c.source.file.str().ends_with("a.bml")) held = held || (c.fill == Fill::freeze && c.end <= 1);
  EXPECT_TRUE(held);
}

TEST(BmlSequence, ReferencesToEarlierBlocksAreTheirPlacedTimes) {
  write("a.bml", block("a", "", R"(<head id="nod" lexeme="NOD" start="1"/>)"));
  write("b.bml", block("b", "MERGE", R"(<faceLexeme id="f" lexeme="RAISE_BROWS" start="a:nod:end+0.25"/>)"));
  const BmlDocument d = read_ok("a.bml\nat 0.5 b.bml\n");
  EXPECT_DOUBLE_EQ(behaviour(d, "b", "f").start, 1 + kNod + 0.25);
}

TEST(BmlSequence, ADocumentAloneIsAOneBlockSequence) {
  write("a.bml", block("a", "APPEND", R"(<head id="nod" lexeme="NOD"/>)"));
  const BmlDocument d = read_ok("# one block\n\na.bml\n");
  EXPECT_EQ(d.block_starts, (std::vector<double>{0}));
  EXPECT_DOUBLE_EQ(behaviour(d, "a", "nod").end, kNod);
}

Diagnostic read_error(const std::string& list) {
  Result<BmlDocument> d = read_list(list);
  EXPECT_FALSE(d);
  return d ? Diagnostic{} : d.error();
}

TEST(BmlSequence, ListErrorsArePlacedInTheList) {
  write("a.bml", block("a", "", R"(<head id="nod" lexeme="NOD"/>)"));
  write("b.bml", block("b", "", R"(<head id="nod" lexeme="NOD"/>)"));
  Diagnostic e = read_error("a.bml\n  missing.bml\n");
  EXPECT_TRUE(e.where.file.str().ends_with("list.bmlseq"));
  EXPECT_EQ(e.where.line, 2);
  EXPECT_EQ(e.where.column, 3);
  e = read_error("at 2 a.bml\nat 1 b.bml\n");
  EXPECT_EQ(e.where.line, 2);
  EXPECT_EQ(e.where.column, 1);
  EXPECT_NE(e.message.find("before the block listed before it"), std::string::npos) << e.message;
  e = read_error("at soon a.bml\n");
  EXPECT_EQ(e.where.line, 1);
  e = read_error("at 1\n");
  EXPECT_EQ(e.where.line, 1);
  e = read_error("# nothing\n");
  EXPECT_EQ(e.where.line, 1);
  e = read_error("../../../outside.bml\n");
  EXPECT_EQ(e.where.line, 1);
}

TEST(BmlSequence, DocumentErrorsArePlacedInTheDocument) {
  write("a.bml", block("a", "", R"(<head id="nod" lexeme="NOD"/>)"));
  write("blend.bml", block("x", "blend", R"(<head id="nod" lexeme="NOD"/>)"));
  Diagnostic e = read_error("a.bml\nblend.bml\n");
  EXPECT_TRUE(e.where.file.str().ends_with("blend.bml")) << format_diagnostic(e);
  EXPECT_EQ(e.where.line, 1);
  EXPECT_NE(e.message.find("not MERGE, APPEND or REPLACE"), std::string::npos);

  write("later.bml", block("b", "", R"(<head id="nod" lexeme="NOD" start="c:nod:end"/>)"));
  e = read_error("a.bml\nlater.bml\n");
  EXPECT_TRUE(e.where.file.str().ends_with("later.bml"));
  EXPECT_EQ(e.where.line, 2);
  EXPECT_NE(e.message.find("not an earlier block"), std::string::npos) << e.message;

  write("nopoint.bml", block("b", "", R"(<head id="nod" lexeme="NOD" start="a:nod:apex"/>)"));
  e = read_error("a.bml\nnopoint.bml\n");
  EXPECT_EQ(e.where.line, 2);

  write("again.bml", block("a", "APPEND", R"(<head id="nod" lexeme="NOD"/>)"));
  e = read_error("a.bml\nagain.bml\n");
  EXPECT_TRUE(e.where.file.str().ends_with("again.bml"));
  EXPECT_NE(e.message.find("second block with id 'a'"), std::string::npos);

  // A block placed after the earlier ones would start before its own start: the reference asks
  // for a time before the block.
  write("early.bml", block("b", "APPEND", R"(<head id="nod" lexeme="NOD" end="a:nod:start"/>)"));
  e = read_error("a.bml\nearly.bml\n");
  EXPECT_TRUE(e.where.file.str().ends_with("early.bml"));
}

TEST(BmlSequence, TheBehaviourLimitCountsEveryBlock) {
  // No namespace: Greta's habit of reusing block ids is a warning there, so only the limit stops it.
  write("a.bml", R"(<bml id="a"><head id="n1" lexeme="NOD"/><head id="n2" lexeme="NOD"/></bml>)");
  std::string list;
  for (int i = 0; i < 5; ++i) list += "a.bml\n";
  ReaderOptions options;
  options.limits.max_runs = 6;
  const std::string path = (fs::path(folder()) / "many.bmlseq").string();
  std::ofstream(path, std::ios::binary) << list;
  Result<BmlDocument> d = load_bml_sequence(path, options);
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().kind, ErrorKind::limit_exceeded) << format_diagnostic(d.error());
}

}  // namespace
}  // namespace fapc::bml

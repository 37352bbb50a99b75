// The reader and writer tables: lookups by extension (the longest wins) and by kind.
#include <gtest/gtest.h>

#include "fapc/pipeline/registry.hpp"

namespace fapc {
namespace {

using pipeline::formats;

TEST(Registry, InputsByExtensionTheLongestMatchWins) {
  EXPECT_EQ(formats().input_for("a/b.fap")->kind, "fap");
  EXPECT_EQ(formats().input_for("b.fap.gz")->kind, "fap");
  EXPECT_EQ(formats().input_for("b.fba.gz")->kind, "fba");
  EXPECT_EQ(formats().input_for("b.mim")->kind, "mimic");
  EXPECT_EQ(formats().input_for("b.xmt")->kind, "xmt");
  EXPECT_EQ(formats().input_for("b.combine")->kind, "combine");
  EXPECT_EQ(formats().input_for("b.txt"), nullptr);
  EXPECT_EQ(formats().input_for("fap"), nullptr);  // an extension, not a name
}

TEST(Registry, OutputsByExtensionTheLongestMatchWins) {
  EXPECT_EQ(formats().output_for("b.xmt")->kind, "xmt");
  EXPECT_EQ(formats().output_for("b.bifs.xmt")->kind, "xmt-bifs");
  EXPECT_EQ(formats().output_for("b.json")->kind, "json");
  EXPECT_EQ(formats().output_for("b.mimic"), nullptr);  // Mimic is read, never written
}

TEST(Registry, ByKindName) {
  for (const char* kind : {"fap", "fba", "mp4", "mimic", "fml", "xmt", "combine"})
    EXPECT_NE(formats().input_named(kind), nullptr) << kind;
  for (const char* kind : {"fap", "fba", "mp4", "xmt", "xmt-bifs", "json", "svg", "timeline"})
    EXPECT_NE(formats().output_named(kind), nullptr) << kind;
  EXPECT_EQ(formats().output_named("fml"), nullptr);
}

TEST(Registry, AnEntryAddedToARegistryIsFoundByItsExtension) {
  pipeline::Registry registry;
  registry.add(pipeline::OutputFormat{
      "shout",
      {".shout"},
      [](const pipeline::Loaded& loaded, const std::string&, const pipeline::ConvertOptions&) -> Result<std::string> {
        return std::to_string(loaded.frames.frames.size()) + " FRAMES\n";
      }});
  const pipeline::OutputFormat* writer = registry.output_for("x.shout");
  ASSERT_NE(writer, nullptr);
  pipeline::Loaded loaded;
  loaded.frames.frames.resize(3);
  EXPECT_EQ(*writer->write(loaded, "x.shout", {}), "3 FRAMES\n");
}

}  // namespace
}  // namespace fapc

// Every SMIL-Agent script of corpus/smil (Xface's, as published) either compiles to a .fap or is
// refused with a positioned error that names a real defect of the file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <map>

#include "fapc/pipeline/convert.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

// The refused files, by their name under corpus/smil, and what the error must say and where.
struct Refusal {
  int line;
  int column;
  std::string says;
};
const std::map<std::string, Refusal> kRefused = {
    // The script names a recording that was never published with it.
    {"bestdpf__xface-new/Faps/externalWav.smil", {3, 60, "speech file 'test.wav': cannot open file"}},
    {"copperdong__Xface/Faps/externalWav.smil", {3, 60, "speech file 'test.wav': cannot open file"}},
};

TEST(SmilCorpus, EveryScriptCompilesToFapOrIsRefusedAtItsDefect) {
  const std::string folder = test::corpus_dir() + "/smil/";
  const std::vector<std::string> files = test::files_under(folder, ".smil");
  EXPECT_EQ(files.size(), 13u);
  const fs::path out = fs::temp_directory_path() / ("fapc-smil-corpus-" + std::to_string(::getpid()));
  fs::create_directories(out);
  for (const std::string& path : files) {
    const std::string name = path.substr(folder.size());
    SCOPED_TRACE(name);
    const fs::path fap = out / "out.fap";
    fs::remove(fap);
    pipeline::ConvertOptions options;
    const pipeline::ConvertResult result = pipeline::convert(path, {{fap.string(), ""}}, options);
    if (const auto refused = kRefused.find(name); refused != kRefused.end()) {
      ASSERT_TRUE(result.error);
      EXPECT_EQ(result.error->where.file, path);
      EXPECT_EQ(result.error->where.line, refused->second.line);
      EXPECT_EQ(result.error->where.column, refused->second.column);
      EXPECT_NE(result.error->message.find(refused->second.says), std::string::npos) << result.error->message;
      EXPECT_FALSE(fs::exists(fap));
      continue;
    }
    ASSERT_FALSE(result.error) << format_diagnostic(*result.error);
    ASSERT_TRUE(fs::exists(fap));
    // Every script says or does something for at least a second.
    Result<pipeline::Loaded> written = pipeline::load(fap.string(), options);
    ASSERT_TRUE(written) << format_diagnostic(written.error());
    EXPECT_GT(written->frames.frames.size(), 25u);
  }
  fs::remove_all(out);
}

// An Xface script named .xml is read by its root (par or seq) as SMIL-Agent, to the same frames.
TEST(SmilCorpus, AScriptNamedXmlIsReadByItsRoot) {
  const std::string script = test::corpus_dir() + "/smil/copperdong__Xface/Faps/actionOnlySeq.smil";
  const fs::path copy = fs::temp_directory_path() / ("fapc-smil-root-" + std::to_string(::getpid()) + ".xml");
  fs::copy_file(script, copy, fs::copy_options::overwrite_existing);
  pipeline::ConvertOptions options;
  options.facts = true;
  Result<pipeline::Loaded> as_xml = pipeline::load(copy.string(), options);
  Result<pipeline::Loaded> as_smil = pipeline::load(script, options);
  fs::remove(copy);
  ASSERT_TRUE(as_xml) << format_diagnostic(as_xml.error());
  ASSERT_TRUE(as_smil) << format_diagnostic(as_smil.error());
  EXPECT_EQ(json_of(as_xml->facts)["format"], "SMIL-Agent");
  EXPECT_EQ(json_of(as_xml->facts)["recognised_by"], "root <seq>");
  ASSERT_EQ(as_xml->frames.frames.size(), as_smil->frames.frames.size());
  for (std::size_t i = 0; i < as_xml->frames.frames.size(); ++i)
    for (int fap = 1; fap <= kFapCount; ++fap)
      ASSERT_EQ(as_xml->frames.frames[i].has(fap) ? as_xml->frames.frames[i].value(fap) : 0,
                as_smil->frames.frames[i].has(fap) ? as_smil->frames.frames[i].value(fap) : 0);
}

}  // namespace
}  // namespace fapc

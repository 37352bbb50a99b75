// SourceText (fapcodec's file_io.hpp): a script's bytes mapped, or inflated when gzip, and
// pages let go that come back when looked at again (a message's source line after the parse).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "fapc/codec/file_io.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

class SourceTextFile : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("fapc-source-text-" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string write(const std::string& name, const std::string& bytes) const {
    const fs::path path = folder_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }
  fs::path folder_;
};

// Some pages' worth of numbered lines, so that release() has whole pages to let go.
std::string long_text() {
  std::string text;
  for (int line = 0; line < 20000; ++line) text += "<line n=\"" + std::to_string(line) + "\"/>\n";
  return text;
}

TEST_F(SourceTextFile, ReadsAFileAndStillReadsItAfterLettingEveryPageGo) {
  const std::string text = long_text();
  const auto source = SourceText::open(write("script.xmt", text));
  ASSERT_TRUE(source.ok()) << format_diagnostic(source.error());
  EXPECT_EQ(source->bytes(), text);
  source->release(text.size() / 2);
  EXPECT_EQ(source->bytes(), text);  // the pages come back from the file
  source->release(text.size());
  EXPECT_EQ(source->bytes().substr(text.size() - 100), text.substr(text.size() - 100));
  EXPECT_EQ(source->bytes(), text);
}

TEST_F(SourceTextFile, InflatesAGzipFile) {
  const std::string text = long_text();
  const auto source = SourceText::open(write("script.xmt.gz", gzip(text)));
  ASSERT_TRUE(source.ok()) << format_diagnostic(source.error());
  EXPECT_EQ(source->bytes(), text);
  source->release(text.size());  // a no-op: the text is held, not mapped
  EXPECT_EQ(source->bytes(), text);
}

TEST_F(SourceTextFile, AnEmptyFileIsEmptyText) {
  const auto source = SourceText::open(write("empty.fml", ""));
  ASSERT_TRUE(source.ok()) << format_diagnostic(source.error());
  EXPECT_TRUE(source->bytes().empty());
  source->release(0);
}

TEST_F(SourceTextFile, AMissingFileOrAFolderIsAnIoError) {
  const auto missing = SourceText::open((folder_ / "missing.fml").string());
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().kind, ErrorKind::io);
  const auto folder = SourceText::open(folder_.string());
  ASSERT_FALSE(folder.ok());
  EXPECT_EQ(folder.error().kind, ErrorKind::io);
}

}  // namespace
}  // namespace fapc

// Outside readers: ffprobe (FFmpeg) and MediaInfo must accept every MP4 the project writes and
// see an FBA stream in it. They are independent implementations: if they reject a file, the file
// is wrong. Both come from Debian (ffmpeg, mediainfo); the README's install step adds them.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "fapc/codec/file_io.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "support/test_support.hpp"
#include "test_tracks.hpp"

namespace fapc::xmt {
namespace {

namespace fs = std::filesystem;

bool have_program(const std::string& name) { return fapc::test::run_shell("command -v " + name).exit_status == 0; }

// The lines of `text` that do not start with `ignored_prefix`.
std::string lines_without(const std::string& text, const std::string& ignored_prefix) {
  std::istringstream in(text);
  std::string line, kept;
  while (std::getline(in, line))
    if (line.rfind(ignored_prefix, 0) != 0) kept += line + '\n';
  return kept;
}

// The [STREAM] block of ffprobe's -show_streams output whose id is `track_id`.
std::string ffprobe_stream(const std::string& out, std::uint32_t track_id) {
  std::ostringstream id;
  id << "id=0x" << std::hex << track_id << '\n';
  std::size_t begin = 0;
  while ((begin = out.find("[STREAM]", begin)) != std::string::npos) {
    const std::size_t end = out.find("[/STREAM]", begin);
    const std::string block = out.substr(begin, end - begin);
    if (block.find(id.str()) != std::string::npos) return block;
    begin = end;
  }
  return {};
}

// What the issue asks of every .mp4: ffprobe reports the Simple Face Animation profile on the FBA
// stream and no errors; mediainfo --Details=1 decodes the FBA object start.
void check_with_outside_readers(const std::string& path) {
  SCOPED_TRACE(path);
  ASSERT_TRUE(have_program("ffprobe")) << "ffprobe missing: apt-get install ffmpeg";
  ASSERT_TRUE(have_program("mediainfo")) << "mediainfo missing: apt-get install mediainfo";
  auto bytes = read_file_bytes(path);
  ASSERT_TRUE(bytes.ok());
  auto mp4 = read_mp4(Bytes(bytes->begin(), bytes->end()), path);
  ASSERT_TRUE(mp4.ok()) << format_diagnostic(mp4.error());
  const Mp4Track* fba = find_fba_track(*mp4);
  ASSERT_NE(fba, nullptr);

  const auto probe = fapc::test::run_shell("ffprobe -v error -show_streams '" + path + "'");
  EXPECT_EQ(probe.exit_status, 0);
  // FFmpeg's MPEG-4 Part 2 *video* decoder may complain about the planes it cannot decode (it has
  // no FBA decoder); anything else on stderr is an error about the file.
  EXPECT_EQ(lines_without(probe.err, "[mpeg4 @"), "");
  const std::string stream = ffprobe_stream(probe.out, fba->id);
  ASSERT_FALSE(stream.empty()) << probe.out;
  EXPECT_NE(stream.find("codec_name=mpeg4\n"), std::string::npos) << stream;
  EXPECT_NE(stream.find("profile=Simple Face Animation Profile\n"), std::string::npos) << stream;
  // ffmpeg names the profile from the high nibble of 0x63 and reports the low nibble as the level.
  EXPECT_NE(stream.find("level=3\n"), std::string::npos) << stream;
  EXPECT_NE(stream.find("nb_frames=" + std::to_string(fba->samples.size()) + "\n"), std::string::npos) << stream;
  EXPECT_NE(stream.find("extradata_size=14\n"), std::string::npos) << stream;

  const auto info = fapc::test::run_shell("mediainfo --Details=1 '" + path + "'");
  EXPECT_EQ(info.exit_status, 0);
  EXPECT_NE(info.out.find("Simple FBA@L1"), std::string::npos);
  EXPECT_NE(info.out.find("visual_object_type:         4 (0x4) - (4 bits) - FBA"), std::string::npos);
  EXPECT_NE(info.out.find("fba_object_start"), std::string::npos);
  EXPECT_NE(info.out.find("start_code:                186 (0xBA)"), std::string::npos);
}

TEST(OutsideReaders, AcceptAWrittenFile) {
  const fs::path path = fs::temp_directory_path() / ("fapc-outside-" + std::to_string(::getpid()) + ".mp4");
  FbaTrackInput track = test::hand_made_track(40, 25, 10);
  track.samples[7].duration = 3;
  auto bytes = write_mp4(track);
  ASSERT_TRUE(bytes.ok());
  ASSERT_TRUE(write_file_atomic(path.string(), std::string(bytes->begin(), bytes->end())).ok());
  check_with_outside_readers(path.string());
  fs::remove(path);
}

TEST(OutsideReaders, AcceptEveryMp4InTheCorpus) {
  // Every .mp4 except the deliberately broken ones of corpus/*-bad/ folders.
  for (const std::string& path : fapc::test::files_under(fapc::test::corpus_dir(), ".mp4"))
    if (path.find("-bad/") == std::string::npos) check_with_outside_readers(path);
}

TEST(OutsideReaders, AcceptTheMp4OfEveryBundledExample) {
  // The README's main job writes these: every example input, whatever its kind, as .mp4.
  const fs::path folder = fs::temp_directory_path() / ("fapc-examples-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  int checked = 0;
  for (const std::string& input : fapc::test::files_under(fapc::test::corpus_dir() + "/examples", "")) {
    const std::string extension = fs::path(input).extension().string();
    if (extension == ".md" || extension == ".xpr" || extension == ".pho") continue;
    const std::string output = (folder / (std::to_string(checked) + ".mp4")).string();
    // As in the main job (batch over the folder): an example may include from the whole folder.
    const auto run =
        fapc::test::run_fapc("compile '" + input + "' -o '" + output + "' --verify --allow-include corpus/examples");
    ASSERT_EQ(run.exit_status, 0) << input << ": " << run.err;
    check_with_outside_readers(output);
    ++checked;
  }
  EXPECT_EQ(checked, 15);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace fapc::xmt

// The real OpenFace and ARKit files of corpus/openface and corpus/arkit (catalog.tsv) convert to
// .fap, .mp4 and .webm, and the face follows the tracked face: where the tracker says the jaw
// opens, the posed face's jaw opens.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "fapc/face/face_pose.hpp"
#include "fapc/face/face_track.hpp"
#include "fapc/pipeline/registry.hpp"
#include "pipeline/pipeline_test_helpers.hpp"

namespace fapc {
namespace {

std::vector<std::string> tracker_files() {
  std::vector<std::string> files = test::files_under(test::corpus_dir() + "/openface", ".csv");
  for (const std::string& f : test::files_under(test::corpus_dir() + "/arkit", ".csv")) files.push_back(f);
  return files;
}

TEST(BridgesCorpus, EveryTrackerFileConvertsToFapMp4AndWebm) {
  const std::vector<std::string> files = tracker_files();
  ASSERT_EQ(files.size(), 6u);
  const test::TempFolder tmp;
  pipeline::ConvertOptions options;
  options.picture.width = 64;  // the video's size does not change what is tested: that it is made
  options.picture.height = 48;
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const std::vector<pipeline::OutputRequest> outputs = {
        {tmp / "a.fap", ""}, {tmp / "a.mp4", ""}, {tmp / "a.webm", ""}};
    const pipeline::ConvertResult result = pipeline::convert(file, outputs, options);
    ASSERT_TRUE(result.ok()) << format_diagnostic(*result.error);
    EXPECT_EQ(result.written.size(), 3u);
    EXPECT_GT(result.frames.count, 1u);
    // The .fap reads back to the frames the CSV became.
    auto back = pipeline::load(tmp / "a.fap", {});
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->frames.frames.size(), result.frames.count);
  }
}

// The take's own rows, read here with a plain split (not the reader): the time of each row from
// its timecode at 60 frames a second (catalog.tsv: FF runs 0..59), and its JawOpen.
struct Row {
  double seconds;
  double jaw_open;
};

std::vector<Row> jaw_open_rows(const std::string& path) {
  std::istringstream text(test::read_text(path));
  std::string line;
  std::getline(text, line);
  std::size_t column = 0;
  {
    std::istringstream header(line);
    std::string name;
    while (std::getline(header, name, ',') && name != "JawOpen") ++column;
  }
  std::vector<Row> rows;
  while (std::getline(text, line)) {
    const double h = std::stod(line.substr(0, 2)), m = std::stod(line.substr(3, 2)), s = std::stod(line.substr(6, 2));
    const double f = std::stod(line.substr(9, line.find(',') - 9));
    std::istringstream row(line);
    std::string cell;
    for (std::size_t i = 0; i <= column; ++i) std::getline(row, cell, ',');
    rows.push_back({(h * 60 + m) * 60 + s + f / 60, std::stod(cell)});
  }
  for (std::size_t i = rows.size(); i-- > 0;) rows[i].seconds -= rows[0].seconds;
  return rows;
}

// How far the posed face's chin has dropped from the neutral face's, in millimetres.
double jaw_drop(const face::FapValues& values) {
  return face::neutral(face::P::chin_bottom).y - face::pose_face(values).at(face::P::chin_bottom).y;
}

TEST(BridgesCorpus, WhereTheTrackerOpensTheJawTheFaceOpensIt) {
  // A range-of-motion take: the jaw opened and closed many times (and held open with the lips
  // closed, which is why the chin is measured, not the lips).
  const std::string take =
      test::corpus_dir() + "/arkit/alexdjulin__LiveLinkFace-CSV-Retarget-For-Motionbuilder/alex_rom_3.csv";
  const std::vector<Row> rows = jaw_open_rows(take);
  auto loaded = pipeline::load(take, {});
  ASSERT_TRUE(loaded.ok()) << format_diagnostic(loaded.error());
  const face::FaceTrack track(loaded->frames);
  double open_sum = 0, closed_sum = 0;
  int open_count = 0, closed_count = 0, wrong = 0;
  std::size_t row = 0;
  for (std::int64_t k = 0; k < track.frame_count(); ++k) {
    const double time = static_cast<double>(k) / loaded->frames.fps;
    while (row + 1 < rows.size() && rows[row + 1].seconds <= time) ++row;
    if (row + 1 >= rows.size()) break;
    // Only frames between two rows that agree: a frame amid an opening or closing is in between.
    const double jaw = rows[row].jaw_open;
    if (std::abs(rows[row + 1].jaw_open - jaw) > 0.1) continue;
    const double drop = jaw_drop(track.at_frame(k));
    if (jaw > 0.5) {
      open_sum += drop, ++open_count;
      if (drop < 5) ++wrong;  // an open jaw drawn less than 5 mm open
    } else if (jaw < 0.05) {
      closed_sum += drop, ++closed_count;
      if (drop > 2) ++wrong;  // a closed jaw drawn open
    }
  }
  ASSERT_GT(open_count, 100);
  ASSERT_GT(closed_count, 100);
  EXPECT_GT(open_sum / open_count, closed_sum / closed_count + 6);
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace fapc

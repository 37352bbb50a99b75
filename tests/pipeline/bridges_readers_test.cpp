// The OpenFace and ARKit CSV readers (docs/bridges.md): what a row becomes, which CSV is which,
// and a positioned error for every malformed row.
#include <gtest/gtest.h>

#include <cmath>

#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/registry.hpp"
#include "pipeline/pipeline_test_helpers.hpp"

namespace fapc {
namespace {

Result<pipeline::Loaded> load_text(const test::TempFolder& tmp, const std::string& name, const std::string& text,
                                   pipeline::ConvertOptions options = {}) {
  EXPECT_TRUE(write_file_atomic(tmp / name, text).ok());
  return pipeline::load(tmp / name, options);
}

void expect_error_at(const Result<pipeline::Loaded>& loaded, int line, int column, const std::string& words) {
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().where.line, line) << loaded.error().message;
  EXPECT_EQ(loaded.error().where.column, column) << loaded.error().message;
  EXPECT_NE(loaded.error().message.find(words), std::string::npos) << loaded.error().message;
}

bool has_warning(const pipeline::Loaded& loaded, const std::string& code) {
  for (const Diagnostic& d : loaded.warnings)
    if (d.code == code) return true;
  return false;
}

// AU 26 at intensity 5 is the table's full jaw drop (420 MNS units); 2.5 is half. Two spaces after
// each comma, as some 1.x files have them. 0.04 s apart: frames at 25 fps fall on the rows.
TEST(OpenFaceCsv, ActionUnitsScaleTheTableRowsAndHeadPoseIsInRadians) {
  const test::TempFolder tmp;
  auto loaded = load_text(tmp, "a.csv",
                          "frame,  timestamp,  confidence,  success,  pose_Rx,  pose_Ry,  pose_Rz,  AU26_r\n"
                          "1,  0,  0.98,  1,  0.1,  -0.2,  0,  5\n"
                          "2,  0.04,  0.98,  1,  0,  0,  0.05,  2.5\n");
  ASSERT_TRUE(loaded.ok()) << format_diagnostic(loaded.error());
  ASSERT_EQ(loaded->frames.frames.size(), 2u);
  const FapFrame& first = loaded->frames.frames[0];
  EXPECT_EQ(first.value(3), 420);
  EXPECT_EQ(first.value(48), 10000);   // 0.1 rad nods down
  EXPECT_EQ(first.value(49), -20000);  // -0.2 rad turns to the face's right
  EXPECT_EQ(loaded->frames.frames[1].value(3), 210);
  EXPECT_EQ(loaded->frames.frames[1].value(50), 5000);
  EXPECT_FALSE(first.has(19));  // no column drives the eyelids
}

TEST(OpenFaceCsv, IrregularRowsAreResampledToTheFrameRate) {
  const test::TempFolder tmp;
  pipeline::ConvertOptions options;
  options.fps = 10;
  // Rows at 0, 0.03 and 0.25 s: frames at 0, 0.1 and 0.2 s interpolate between the last two.
  auto loaded = load_text(tmp, "a.csv", "timestamp, AU26_r\n0, 0\n0.03, 0\n0.25, 5\n", options);
  ASSERT_TRUE(loaded.ok()) << format_diagnostic(loaded.error());
  ASSERT_EQ(loaded->frames.frames.size(), 3u);
  EXPECT_EQ(loaded->frames.fps, 10);
  EXPECT_EQ(loaded->frames.frames[0].value(3), 0);
  EXPECT_EQ(loaded->frames.frames[1].value(3), std::lround(420 * (0.1 - 0.03) / 0.22));
  EXPECT_EQ(loaded->frames.frames[2].value(3), std::lround(420 * (0.2 - 0.03) / 0.22));
}

TEST(OpenFaceCsv, UntrustedRowsHoldTheLastTrackedFaceWithAWarning) {
  const test::TempFolder tmp;
  auto loaded = load_text(tmp, "a.csv",
                          "frame, face_id, timestamp, confidence, success, AU26_r\n"
                          "1, 0, 0, 0.9, 1, 5\n"
                          "2, 0, 0.04, 0.9, 0, 0\n"  // lost by the tracker
                          "3, 0, 0.08, 0.2, 1, 0\n"  // too unsure
                          "3, 1, 0.08, 0.9, 1, 1\n"  // another face
                          "4, 0, 0.12, 0.9, 1, 0\n");
  ASSERT_TRUE(loaded.ok()) << format_diagnostic(loaded.error());
  ASSERT_EQ(loaded->frames.frames.size(), 4u);
  EXPECT_EQ(loaded->frames.frames[1].value(3), 420);
  EXPECT_EQ(loaded->frames.frames[2].value(3), 420);
  EXPECT_EQ(loaded->frames.frames[3].value(3), 0);
  EXPECT_TRUE(has_warning(*loaded, "openface.untrusted_rows"));
  EXPECT_TRUE(has_warning(*loaded, "openface.other_faces"));
  for (const Diagnostic& d : loaded->warnings) {
    if (d.code == "openface.untrusted_rows") {
      EXPECT_EQ(d.where.line, 3);
    }
  }
}

TEST(OpenFaceCsv, GazeAnglesAndVectorsTurnTheEyes) {
  const test::TempFolder tmp;
  auto angles = load_text(tmp, "a.csv", "timestamp,gaze_angle_x,gaze_angle_y\n0,0.2,-0.1\n");
  ASSERT_TRUE(angles.ok()) << format_diagnostic(angles.error());
  EXPECT_EQ(angles->frames.frames[0].value(23), 20000);
  EXPECT_EQ(angles->frames.frames[0].value(24), 20000);
  EXPECT_EQ(angles->frames.frames[0].value(25), -10000);
  // 1.x: eye 0 (the face's right eye) looks straight at the camera, eye 1 to the image's right.
  auto vectors =
      load_text(tmp, "b.csv", "timestamp,gaze_0_x,gaze_0_y,gaze_0_z,gaze_1_x,gaze_1_y,gaze_1_z\n0,0,0,-1,0.6,0,-0.8\n");
  ASSERT_TRUE(vectors.ok()) << format_diagnostic(vectors.error());
  EXPECT_EQ(vectors->frames.frames[0].value(24), 0);
  EXPECT_EQ(vectors->frames.frames[0].value(23), std::lround(std::atan2(0.6, 0.8) * 1e5));
}

TEST(ArkitCsv, LiveLinkFaceTakesAndMediaPipeNamesReadTheSame) {
  const test::TempFolder tmp;
  // 60-fps timecode (a frame field above 29), a row every other frame: 30 rows a second.
  auto llf = load_text(tmp, "a.csv",
                       "Timecode,BlendShapeCount,JawOpen,EyeBlinkLeft,LeftEyeYaw\n"
                       "10:00:00:58.000,3,0.5,1,0.1\n"
                       "10:00:01:00.000,3,0.5,1,0.1\n");
  ASSERT_TRUE(llf.ok()) << format_diagnostic(llf.error());
  ASSERT_EQ(llf->frames.frames.size(), 1u);        // 1/30 s: one frame at 25 fps
  EXPECT_EQ(llf->frames.frames[0].value(3), 430);  // half of jawOpen's 860
  EXPECT_EQ(llf->frames.frames[0].value(19), 1024);
  EXPECT_EQ(llf->frames.frames[0].value(23), -10000);  // the angle column, not the shapes
  auto mediapipe = load_text(tmp, "b.csv", "timestamp_ms,_neutral,jawOpen,eyeBlinkLeft\n0,0.9,0.5,1\n80,0.9,0.5,1\n");
  ASSERT_TRUE(mediapipe.ok()) << format_diagnostic(mediapipe.error());
  ASSERT_EQ(mediapipe->frames.frames.size(), 3u);
  EXPECT_EQ(mediapipe->frames.frames[2].value(3), 430);
  EXPECT_EQ(mediapipe->frames.frames[2].value(19), 1024);
}

TEST(TrackerCsv, WhichCsvIsDecidedByTheHeader) {
  const test::TempFolder tmp;
  auto frames_csv = load_text(tmp, "a.csv", "frame,time_s,open_jaw\n0,0,100\n");
  ASSERT_FALSE(frames_csv.ok());
  EXPECT_EQ(frames_csv.error().kind, ErrorKind::unsupported);
  EXPECT_NE(frames_csv.error().message.find("frames CSV"), std::string::npos);
  auto other = load_text(tmp, "b.csv", "name,age\nx,1\n");
  ASSERT_FALSE(other.ok());
  EXPECT_EQ(other.error().kind, ErrorKind::unsupported);
  EXPECT_EQ(pipeline::formats().input_for("x.csv")->kind, "csv");
  EXPECT_EQ(pipeline::formats().input_for("x.arkit.csv")->kind, "arkit");
  EXPECT_EQ(pipeline::formats().input_for("x.au.csv")->kind, "openface");
}

TEST(TrackerCsv, MalformedRowsArePositioned) {
  const test::TempFolder tmp;
  const std::string header = "timestamp, confidence, AU26_r\n";
  expect_error_at(load_text(tmp, "a.csv", header + "0, 0.9, 1\n0.04, 0.9, x\n"), 3, 12, "not a number");
  expect_error_at(load_text(tmp, "b.csv", header + "0, 0.9\n"), 2, 7, "2 cells");
  expect_error_at(load_text(tmp, "c.csv", header + "0, 0.9, 1, 4\n"), 2, 12, "more cells");
  expect_error_at(load_text(tmp, "d.csv", header + "1, 0.9, 1\r\n0.5, 0.9, 1\r\n"), 3, 1, "goes back");
  expect_error_at(load_text(tmp, "e.csv", "confidence, AU26_r\n0.9, 1\n"), 1, 1, "timestamp");
  expect_error_at(load_text(tmp, "f.csv", "timestamp, AU26_r, AU26_r\n"), 1, 20, "named twice");
  expect_error_at(load_text(tmp, "g.csv", header), 1, 1, "without any data row");
  expect_error_at(load_text(tmp, "h.csv", "Timecode,JawOpen\n10:00:00:00.000,0.1\n10:61:00:00.000,0.1\n"), 3, 1,
                  "not a timecode");
  expect_error_at(load_text(tmp, "i.csv", "Timecode,JawOpen\n10:00:00:00.000,1e999\n"), 2, 17, "not a number");
}

TEST(TrackerCsv, LimitsAreCheckedBeforeTheFramesAreMade) {
  const test::TempFolder tmp;
  pipeline::ConvertOptions options;
  options.limits.max_frames = 100;
  auto long_take = load_text(tmp, "a.csv", "timestamp, AU26_r\n0, 1\n3600, 1\n", options);
  ASSERT_FALSE(long_take.ok());
  EXPECT_EQ(long_take.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(long_take.error().where.line, 3);
  EXPECT_NE(long_take.error().message.find("--max-frames"), std::string::npos);
  // A time too large for any frame number (the count is compared before it is an integer).
  auto far = load_text(tmp, "c.csv", "timestamp, AU26_r\n0, 1\n1e308, 1\n", options);
  ASSERT_FALSE(far.ok());
  EXPECT_EQ(far.error().kind, ErrorKind::limit_exceeded);
  std::string wide = "timestamp";
  for (int i = 0; i < 5000; ++i) wide += ",c" + std::to_string(i);
  auto too_wide = load_text(tmp, "b.csv", wide + "\n");
  ASSERT_FALSE(too_wide.ok());
  EXPECT_NE(too_wide.error().message.find("more than the limit of 4096"), std::string::npos);
}

}  // namespace
}  // namespace fapc

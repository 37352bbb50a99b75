// The .glb and .gltf outputs as outside tools see them: the Khronos glTF validator (vendored npm
// package, run by node) finds no error in any file written here, and an importer's reading of the
// file (tests/head3d/gltf_pose.py: its own parser, sparse accessors, keyframe sampling, neutral +
// sum of weight x target, node rotations) puts the head, the lids and the jaw where fapc::face
// puts them for the same frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fapc/codec/fap_file.hpp"
#include "fapc/face/face_pose.hpp"
#include "fapc/face/face_track.hpp"
#include "fapc/head3d/arkit_morphs.hpp"
#include "fapc/head3d/head_mesh.hpp"
#include "fapc/head3d/head_morphs.hpp"
#include "support/test_support.hpp"

namespace fapc::head3d {
namespace {

using face::P;

std::string out_dir() {
  const std::string dir = test::binary_dir() + "/head3d";
  std::filesystem::create_directories(dir);
  return dir;
}

nlohmann::json validate(const std::string& file) {
  const test::CommandRun run = test::run_shell("node " + test::source_dir() + "/tests/head3d/validate_gltf.js " + file);
  EXPECT_EQ(run.exit_status, 0) << run.out << run.err;
  return nlohmann::json::parse(run.out);
}

nlohmann::json importer_pose(const std::string& file, double time, const std::vector<int>& vertices) {
  std::string list;
  for (int v : vertices) list += (list.empty() ? "" : ",") + std::to_string(v);
  const test::CommandRun run = test::run_shell("python3 " + test::source_dir() + "/tests/head3d/gltf_pose.py " + file +
                                               " --time " + std::to_string(time) + " --vertices=" + list);
  EXPECT_EQ(run.exit_status, 0) << run.err;
  return nlohmann::json::parse(run.out);
}

int vertex_of(P p) { return head_mesh().feature_vertex[static_cast<std::size_t>(p)]; }

Vec3 world(const nlohmann::json& pose, int v) {
  const auto& p = pose["vertices"][std::to_string(v)];
  return Vec3{p[0].get<double>() * 1000, p[1].get<double>() * 1000, p[2].get<double>() * 1000};
}

double distance(Vec3 a, Vec3 b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

TEST(GltfOutput, Figure3ValidatesAndTurnsAndClosesTheEyeWhereTheProgramSays) {
  const std::string glb = out_dir() + "/f3.glb", fap = out_dir() + "/f3.fap";
  ASSERT_EQ(test::run_fapc("compile corpus/examples/mimic/figure3.mimic -o " + glb).exit_status, 0);
  ASSERT_EQ(test::run_fapc("compile corpus/examples/mimic/figure3.mimic -o " + fap).exit_status, 0);
  const nlohmann::json report = validate(glb);
  EXPECT_EQ(report["errors"], 0) << report.dump();
  EXPECT_EQ(report["animationCount"], 1);
  EXPECT_EQ(report["hasMorphTargets"], true);

  const auto read = read_fap_text(test::read_text(fap), fap);
  ASSERT_TRUE(static_cast<bool>(read));
  const face::FaceTrack track(read->sequence);
  // At 10 s the program has turned the head (head_rot_y, head_rot_x held from 5 to 15 s) and the
  // left eyelid is at 0.8 (6 s + 3 s in, held 2 s); at 0 s nothing has moved.
  const std::vector<int> points = {vertex_of(P::nose_tip), vertex_of(P::lid_t_l), vertex_of(P::lid_b_l),
                                   vertex_of(P::lid_t_r),  vertex_of(P::lid_b_r), vertex_of(P::chin_bottom)};
  for (const double t : {0.0, 10.0, 12.0}) {
    const nlohmann::json pose = importer_pose(glb, t, points);
    const face::FacePose face_pose = face::pose_face(track.at_time(t));
    // The head node's rotation is the 2D face's head rotation.
    const auto& q = pose["rotations"]["head"];
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(r[i][j], face_pose.head.m[i][j], 1e-5) << t;
    // The nose tip's vertex (the mesh passes through 9.3) is where the 2D face puts 9.3.
    EXPECT_LT(distance(world(pose, points[0]), face_pose.at(P::nose_tip)), 1.0) << t;
    // The lids' openings, top to bottom (a distance, so the head's rotation does not enter):
    // the 2D face's 3.1-3.3 and 3.2-3.4 within 0.5 mm.
    EXPECT_NEAR(distance(world(pose, points[1]), world(pose, points[2])),
                distance(face_pose.at(P::lid_t_l), face_pose.at(P::lid_b_l)), 0.5)
        << t;
    EXPECT_NEAR(distance(world(pose, points[3]), world(pose, points[4])),
                distance(face_pose.at(P::lid_t_r), face_pose.at(P::lid_b_r)), 0.5)
        << t;
    EXPECT_LT(distance(world(pose, points[5]), face_pose.at(P::chin_bottom)), 1.0) << t;
    if (t == 10.0) {
      EXPECT_GT(std::abs(face_pose.head.m[0][2]), 0.2);                            // turned
      EXPECT_LT(distance(face_pose.at(P::lid_t_l), face_pose.at(P::lid_b_l)), 4);  // nearly closed
    }
  }
}

TEST(GltfOutput, EveryKindOfInputWritesAValidGlbAndGltf) {
  for (const std::string input : {"corpus/examples/fap/joy.fap", "corpus/examples/fml/tour.fml",
                                  "corpus/examples/fap/greta-lips.fap", "corpus/examples/fap/vreng-joy.fap"}) {
    const std::string stem = std::filesystem::path(input).stem().string();
    for (const std::string ext : {".glb", ".gltf"}) {
      const std::string out = out_dir() + "/" + stem + ext;
      const test::CommandRun run = test::run_fapc("compile " + input + " -o " + out);
      ASSERT_EQ(run.exit_status, 0) << run.err;
      EXPECT_EQ(validate(out)["errors"], 0) << out;
    }
  }
}

// The sampled weights are the frame's values / 1024 (joy.fap drives the lip corners).
TEST(GltfOutput, WeightsAreTheFramesValuesOver1024) {
  const std::string glb = out_dir() + "/joy-weights.glb", fap = test::corpus_dir() + "/examples/fap/joy.fap";
  ASSERT_EQ(test::run_fapc("compile corpus/examples/fap/joy.fap -o " + glb).exit_status, 0);
  const auto read = read_fap_text(test::read_text(fap), fap);
  ASSERT_TRUE(static_cast<bool>(read));
  const face::FaceTrack track(read->sequence);
  const double t = 2.0;
  const nlohmann::json pose = importer_pose(glb, t, {});
  const face::FapValues paired = face::with_lip_pairs(track.at_time(t));
  int checked = 0;
  for (const MorphTarget& target : morph_targets()) {
    if (target.fap == 0) continue;
    EXPECT_NEAR(pose["weights"][target.name].get<double>(), paired[static_cast<std::size_t>(target.fap - 1)] / 1024,
                1e-6)
        << target.name;
    if (paired[static_cast<std::size_t>(target.fap - 1)] != 0) ++checked;
  }
  EXPECT_GT(checked, 10);
}

// --morphs arkit: 52 targets named as ARKit's blendshapes, each the sum of its FAPs' targets at the
// amounts of the vocabulary's table (read here from the .tsv itself), valid for the Khronos
// validator, and the program's eye closing still closes the lids.
TEST(GltfOutput, ArkitMorphsValidateAndFollowTheVocabularyTable) {
  const std::string glb = out_dir() + "/f3-arkit.glb", fap = out_dir() + "/f3-arkit.fap";
  ASSERT_EQ(test::run_fapc("compile corpus/examples/mimic/figure3.mimic -o " + glb + " --morphs arkit").exit_status, 0);
  ASSERT_EQ(test::run_fapc("compile corpus/examples/mimic/figure3.mimic -o " + fap).exit_status, 0);
  const nlohmann::json report = validate(glb);
  EXPECT_EQ(report["errors"], 0) << report.dump();
  EXPECT_EQ(report["warnings"], 0) << report.dump();
  EXPECT_EQ(report["hasMorphTargets"], true);

  const auto read = read_fap_text(test::read_text(fap), fap);
  ASSERT_TRUE(static_cast<bool>(read));
  const face::FaceTrack track(read->sequence);
  const std::vector<int> lids = {vertex_of(P::lid_t_l), vertex_of(P::lid_b_l)};
  for (const double t : {0.0, 10.0, 12.0}) {
    const nlohmann::json pose = importer_pose(glb, t, lids);
    EXPECT_EQ(pose["weights"].size(), 52u);
    for (const char* name : {"eyeBlinkLeft", "jawOpen", "mouthSmileLeft", "browInnerUp", "tongueOut"})
      EXPECT_TRUE(pose["weights"].contains(name)) << name;
    // The left lid's opening (figure3 closes that eye to 0.8 at 10 s) within 0.5 mm of the 2D face's.
    const face::FacePose face_pose = face::pose_face(track.at_time(t));
    EXPECT_NEAR(distance(world(pose, lids[0]), world(pose, lids[1])),
                distance(face_pose.at(P::lid_t_l), face_pose.at(P::lid_b_l)), 0.5)
        << t;
  }

  // jawOpen is open_jaw's target times its amount / 1024 (its one row of the table).
  const std::string table = test::read_text(test::source_dir() + "/transcoder/vocabulary/data/arkit_faps.tsv");
  const std::size_t at = table.find("\njawOpen\topen_jaw\t");
  ASSERT_NE(at, std::string::npos);
  std::istringstream row(table.substr(at + 1));
  std::string shape, fap_name, direction;
  double amount = 0;
  row >> shape >> fap_name >> direction >> amount;
  const auto named = [](const std::vector<MorphTarget>& targets, const std::string& name) -> const MorphTarget* {
    for (const MorphTarget& t : targets)
      if (t.name == name) return &t;
    return nullptr;
  };
  const MorphTarget* jaw = named(morph_targets(), fap_name);
  const MorphTarget* jaw_open = named(arkit_targets(), shape);
  ASSERT_TRUE(jaw && jaw_open);
  ASSERT_EQ(jaw_open->vertices, jaw->vertices);
  for (std::size_t i = 0; i < jaw->vertices.size(); ++i)
    EXPECT_LT(distance(jaw_open->displacements[i], (amount / 1024) * jaw->displacements[i]), 1e-9);
}

// Blender's own glTF importer (Debian's blender, background mode) reads f3.glb and f3-arkit.glb:
// the head, the eyes, every target as a shape key in order, and at 0, 10 and 12 s the same
// rotations and weights as the tests' importer. Skipped where Blender is not installed.
TEST(GltfOutput, BlenderImportsTheHeadItsShapeKeysAndTheAnimation) {
  if (test::run_shell("command -v blender").exit_status != 0) GTEST_SKIP() << "Blender is not installed";
  for (const bool arkit : {false, true}) {
    const std::string glb = out_dir() + (arkit ? "/f3-blender-arkit.glb" : "/f3-blender.glb");
    ASSERT_EQ(test::run_fapc("compile corpus/examples/mimic/figure3.mimic -o " + glb + (arkit ? " --morphs arkit" : ""))
                  .exit_status,
              0);
    const test::CommandRun run =
        test::run_shell("blender -b --factory-startup --python-exit-code 1 --python " + test::source_dir() +
                        "/tests/head3d/blender_import.py -- " + glb + " 0 10 12");
    ASSERT_EQ(run.exit_status, 0) << run.err;
    const std::size_t at = run.out.find("BLENDER-IMPORT ");
    ASSERT_NE(at, std::string::npos) << run.out;
    const auto blender = nlohmann::json::parse(run.out.substr(at + 15, run.out.find('\n', at) - at - 15));
    for (const char* name : {"head", "eye_l", "eye_r"})
      EXPECT_NE(std::find(blender["objects"].begin(), blender["objects"].end(), name), blender["objects"].end())
          << name;
    // Blender keeps a vertex per primitive that uses it: at least the mesh's own.
    EXPECT_GE(blender["vertices"].get<std::size_t>(), head_mesh().positions.size());
    std::vector<std::string> names;
    for (const MorphTarget& t : arkit ? arkit_targets() : morph_targets()) names.push_back(t.name);
    EXPECT_EQ(blender["shape_keys"].get<std::vector<std::string>>(), names);
    for (const auto& pose : blender["poses"]) {
      const double t = pose["time"];
      const nlohmann::json ours = importer_pose(glb, t, {});
      for (const std::string node : {"head", "eye_l", "eye_r"}) {
        double dot = 0;  // q and -q are the same rotation
        for (int i = 0; i < 4; ++i)
          dot += pose["rotations"][node][i].get<double>() * ours["rotations"][node][i].get<double>();
        EXPECT_NEAR(std::abs(dot), 1.0, 1e-5) << node << " at " << t;
      }
      for (const std::string& name : names)
        EXPECT_NEAR(pose["weights"][name].get<double>(), ours["weights"][name].get<double>(), 1e-4)
            << name << " at " << t;
    }
  }
}

}  // namespace
}  // namespace fapc::head3d

#include "fapc/head3d/gltf_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "fapc/face/face_model.hpp"
#include "fapc/head3d/arkit_morphs.hpp"
#include "fapc/head3d/head_mesh.hpp"
#include "fapc/head3d/head_morphs.hpp"

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "fapc/head3d/codes.hpp"

namespace fapc::head3d {

namespace {

// glTF's unit is the metre; the face model's the millimetre.
constexpr double kMetre = 1e-3;

// The whole binary buffer, with the views and accessors written into `model` as data is added.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) { model_.buffers.emplace_back(); }

  // A buffer view of raw bytes (4-byte aligned); returns its index.
  int view(const void* data, std::size_t bytes, int target) {
    std::vector<unsigned char>& b = model_.buffers[0].data;
    while (b.size() % 4 != 0) b.push_back(0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = b.size();
    v.byteLength = bytes;
    v.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    b.insert(b.end(), p, p + bytes);
    model_.bufferViews.push_back(v);
    return static_cast<int>(model_.bufferViews.size() - 1);
  }

  int accessor(tinygltf::Accessor a) {
    model_.accessors.push_back(std::move(a));
    return static_cast<int>(model_.accessors.size() - 1);
  }

  // VEC3 floats with their min and max (POSITION needs them).
  int vec3(const std::vector<Vec3>& values, double scale, bool bounds, int target = TINYGLTF_TARGET_ARRAY_BUFFER) {
    std::vector<float> flat;
    flat.reserve(values.size() * 3);
    tinygltf::Accessor a;
    a.minValues.assign(3, std::numeric_limits<double>::infinity());
    a.maxValues.assign(3, -std::numeric_limits<double>::infinity());
    for (const Vec3& v : values)
      for (int k = 0; k < 3; ++k) {
        const float f = static_cast<float>((k == 0 ? v.x : k == 1 ? v.y : v.z) * scale);
        flat.push_back(f);
        a.minValues[static_cast<std::size_t>(k)] = std::min<double>(a.minValues[static_cast<std::size_t>(k)], f);
        a.maxValues[static_cast<std::size_t>(k)] = std::max<double>(a.maxValues[static_cast<std::size_t>(k)], f);
      }
    if (!bounds) a.minValues.clear(), a.maxValues.clear();
    a.bufferView = view(flat.data(), flat.size() * sizeof(float), target);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC3;
    a.count = values.size();
    return accessor(std::move(a));
  }

  int indices(const std::vector<std::uint32_t>& triangles) {
    std::vector<std::uint16_t> shorts(triangles.begin(), triangles.end());
    tinygltf::Accessor a;
    a.bufferView = view(shorts.data(), shorts.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = shorts.size();
    return accessor(std::move(a));
  }

  // A morph target's POSITION deltas as a sparse accessor: only the vertices it moves are stored.
  int sparse_target(const MorphTarget& t, std::size_t vertex_count) {
    tinygltf::Accessor a;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC3;
    a.count = vertex_count;
    a.minValues.assign(3, 0);  // the vertices not listed stay at 0
    a.maxValues.assign(3, 0);
    std::vector<float> values;
    for (const Vec3& d : t.displacements)
      for (int k = 0; k < 3; ++k) {
        const float f = static_cast<float>((k == 0 ? d.x : k == 1 ? d.y : d.z) * kMetre);
        values.push_back(f);
        a.minValues[static_cast<std::size_t>(k)] = std::min<double>(a.minValues[static_cast<std::size_t>(k)], f);
        a.maxValues[static_cast<std::size_t>(k)] = std::max<double>(a.maxValues[static_cast<std::size_t>(k)], f);
      }
    if (t.vertices.empty()) return accessor(std::move(a));  // all zeros: no buffer view at all
    a.sparse.isSparse = true;
    a.sparse.count = static_cast<int>(t.vertices.size());
    std::vector<std::uint16_t> idx(t.vertices.begin(), t.vertices.end());
    a.sparse.indices.bufferView = view(idx.data(), idx.size() * 2, 0);
    a.sparse.indices.byteOffset = 0;
    a.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    a.sparse.values.bufferView = view(values.data(), values.size() * sizeof(float), 0);
    a.sparse.values.byteOffset = 0;
    return accessor(std::move(a));
  }

  int floats(const std::vector<float>& values, int type, bool bounds) {
    tinygltf::Accessor a;
    a.bufferView = view(values.data(), values.size() * sizeof(float), 0);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = type;
    a.count = values.size() / (type == TINYGLTF_TYPE_VEC4 ? 4 : 1);
    if (bounds && !values.empty()) {
      a.minValues = {*std::min_element(values.begin(), values.end())};
      a.maxValues = {*std::max_element(values.begin(), values.end())};
    }
    return accessor(std::move(a));
  }

 private:
  tinygltf::Model& model_;
};

int add_material(tinygltf::Model& model, Material m) {
  tinygltf::Material mat;
  mat.name = std::string(material_name(m));
  const auto rgb = material_colour(m);
  mat.pbrMetallicRoughness.baseColorFactor = {rgb[0], rgb[1], rgb[2], 1.0};
  mat.pbrMetallicRoughness.metallicFactor = 0;
  const bool wet = m == Material::sclera || m == Material::iris || m == Material::pupil || m == Material::teeth;
  mat.pbrMetallicRoughness.roughnessFactor = wet ? 0.3 : 0.75;
  model.materials.push_back(mat);
  return static_cast<int>(model.materials.size() - 1);
}

void add_quaternion(std::vector<float>& out, const Quaternion& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double c : q) out.push_back(static_cast<float>(c / n));
}

std::vector<double> metres(Vec3 v) { return {v.x * kMetre, v.y * kMetre, v.z * kMetre}; }

}  // namespace

Result<std::string> head_gltf(const FapSequence& sequence, const GltfOptions& options, const std::string& where) {
  const HeadMesh& head = head_mesh();
  const EyeballMesh& eye = eyeball_mesh();
  const bool arkit = options.names == MorphNames::arkit;
  const std::vector<MorphTarget>& targets = arkit ? arkit_targets() : morph_targets();
  // The glb's BIN chunk and every glTF byte length are 32-bit: 4 GiB at most. Each frame takes
  // one float per target and three quaternions.
  const std::int64_t frames = sequence.frames.empty() ? 0 : sequence.frames.back().number + 1;
  const double frame_bytes = 4.0 * (static_cast<double>(targets.size()) + 13);
  if (static_cast<double>(frames) * frame_bytes > 2e9)
    return make_error(codes::gltf::too_long, Location::whole_file(where),
                      "a glTF animation of " + std::to_string(frames) +
                          " frames would pass glTF's 32-bit buffer sizes; split the input");

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "fapc";
  BufferBuilder buffer(model);
  std::vector<int> material_of(static_cast<std::size_t>(Material::count), -1);
  auto material = [&](Material m) {
    int& index = material_of[static_cast<std::size_t>(m)];
    if (index < 0) index = add_material(model, m);
    return index;
  };

  // The head: vertices relative to 7.1, the point it turns about (its node's translation).
  const Vec3 pivot = face::neutral(face::P::spine_top);
  std::vector<Vec3> relative;
  relative.reserve(head.positions.size());
  for (const Vec3& p : head.positions) relative.push_back(p - pivot);
  const int positions = buffer.vec3(relative, kMetre, true);
  const int normals = buffer.vec3(head.normals, 1, false);
  std::vector<int> target_accessors;
  for (const MorphTarget& t : targets) target_accessors.push_back(buffer.sparse_target(t, head.positions.size()));
  // One primitive per part: the parts share their mesh's vertices (and its targets).
  auto primitive = [&](int position_accessor, int normal_accessor, const Part& part) {
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = position_accessor;
    prim.attributes["NORMAL"] = normal_accessor;
    prim.indices = buffer.indices(part.triangles);
    prim.material = material(part.material);
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    return prim;
  };
  tinygltf::Mesh mesh;
  mesh.name = "head";
  for (const Part& part : head.parts) {
    tinygltf::Primitive prim = primitive(positions, normals, part);
    for (int a : target_accessors) prim.targets.push_back({{"POSITION", a}});
    mesh.primitives.push_back(prim);
  }
  mesh.weights.assign(targets.size(), 0.0);
  tinygltf::Value::Array names;
  for (const MorphTarget& t : targets) names.emplace_back(t.name);
  mesh.extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(names)}});
  model.meshes.push_back(mesh);

  tinygltf::Mesh eyeball;
  eyeball.name = "eyeball";
  {
    const int p = buffer.vec3(eye.positions, kMetre, true), n = buffer.vec3(eye.normals, 1, false);
    for (const Part& part : eye.parts) eyeball.primitives.push_back(primitive(p, n, part));
  }
  model.meshes.push_back(eyeball);

  tinygltf::Node head_node;
  head_node.name = "head";
  head_node.mesh = 0;
  head_node.translation = metres(pivot);
  head_node.children = {1, 2};
  model.nodes.push_back(head_node);
  for (int e = 0; e < 2; ++e) {
    tinygltf::Node n;
    n.name = e == 0 ? "eye_l" : "eye_r";
    n.mesh = 1;
    n.translation = metres(eyeball_centre(e) - pivot);
    model.nodes.push_back(n);
  }
  tinygltf::Scene scene;
  scene.name = sequence.name.empty() ? "fapc" : sequence.name;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  // The animation: one keyframe per grid frame at k / fps seconds.
  std::vector<float> times, weights, head_rotation, eye_rotation[2];
  const int fps = sequence.fps > 0 ? sequence.fps : 25;
  for_each_head_frame(sequence, [&](const HeadFrame& f) {
    times.push_back(static_cast<float>(static_cast<double>(times.size()) / fps));
    for (double w : arkit ? arkit_weights(f) : f.weights) weights.push_back(static_cast<float>(w));
    add_quaternion(head_rotation, f.head);
    add_quaternion(eye_rotation[0], f.eyes[0]);
    add_quaternion(eye_rotation[1], f.eyes[1]);
  });
  if (!times.empty()) {
    tinygltf::Animation animation;
    animation.name = scene.name;
    const int input = buffer.floats(times, TINYGLTF_TYPE_SCALAR, true);
    auto channel = [&](const std::vector<float>& output, int type, int node, const char* path) {
      tinygltf::AnimationSampler sampler;
      sampler.input = input;
      sampler.output = buffer.floats(output, type, false);
      sampler.interpolation = "LINEAR";
      animation.samplers.push_back(sampler);
      tinygltf::AnimationChannel c;
      c.sampler = static_cast<int>(animation.samplers.size() - 1);
      c.target_node = node;
      c.target_path = path;
      animation.channels.push_back(c);
    };
    channel(weights, TINYGLTF_TYPE_SCALAR, 0, "weights");
    channel(head_rotation, TINYGLTF_TYPE_VEC4, 0, "rotation");
    channel(eye_rotation[0], TINYGLTF_TYPE_VEC4, 1, "rotation");
    channel(eye_rotation[1], TINYGLTF_TYPE_VEC4, 2, "rotation");
    model.animations.push_back(animation);
  }
  model.buffers[0].data.resize((model.buffers[0].data.size() + 3) / 4 * 4, 0);

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, !options.binary, options.binary))
    return make_error(codes::gltf::write_failed, Location::whole_file(where), "tinygltf could not write the glTF");
  return out.str();
}

}  // namespace fapc::head3d

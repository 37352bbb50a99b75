// Face rendering speed: pictures per second at 640x480 (target: faster than real time at 25 fps
// on one core), and a 60-second animation written as .webm (target: under 10 s). The animation
// moves the jaw, lips, lids, brows, eyes and head together, so every part is drawn each frame.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "fapc/face/renderer.hpp"
#include "fapc/face/webm.hpp"
#include "fapc/head3d/gltf_writer.hpp"
#include "fapc/head3d/head_morphs.hpp"

namespace {

fapc::FapSequence sixty_seconds() {
  fapc::FapSequence s;
  s.fps = 25;
  for (int i = 0; i < 60 * 25; ++i) {
    const double t = i / 25.0;
    fapc::FapFrame f;
    f.number = i;
    f.set(3, static_cast<int>(400 + 400 * std::sin(t * 5)));
    for (int fap : {6, 7, 53, 54}) f.set(fap, static_cast<int>(150 * std::sin(t * 1.3)));
    for (int fap : {19, 20}) f.set(fap, std::fmod(t, 3.0) < 0.2 ? 1024 : 0);
    for (int fap : {31, 32, 33, 34}) f.set(fap, static_cast<int>(200 * std::sin(t)));
    f.set(23, static_cast<int>(20000 * std::sin(t * 0.7)));
    f.set(24, static_cast<int>(20000 * std::sin(t * 0.7)));
    f.set(49, static_cast<int>(40000 * std::sin(t * 0.4)));
    f.set(48, static_cast<int>(15000 * std::sin(t * 0.9)));
    f.set(50, static_cast<int>(8000 * std::sin(t * 0.5)));
    s.frames.push_back(f);
  }
  return s;
}

// CPU time of this process: on a shared machine the wall clock also counts other programs' turns.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main() {
  const fapc::FapSequence sequence = sixty_seconds();
  const fapc::face::FaceTrack track(sequence);
  fapc::face::FaceRenderer renderer(640, 480);
  auto start = std::chrono::steady_clock::now();
  double cpu_start = cpu_seconds();
  std::uint32_t checksum = 0;
  for (std::int64_t k = 0; k < track.frame_count(); ++k) checksum ^= renderer.render(track.at_frame(k)).at(320, 240);
  const double render_seconds = seconds_since(start);
  const double render_cpu = cpu_seconds() - cpu_start;
  const double frames = static_cast<double>(track.frame_count());
  std::printf(
      "render 640x480: %lld frames in %.2f s CPU (%.2f s wall) = %.0f frames/s per core "
      "(%.1fx real time at 25 fps) [%08x]\n",
      static_cast<long long>(track.frame_count()), render_cpu, render_seconds, frames / render_cpu,
      frames / render_cpu / 25, checksum);
  start = std::chrono::steady_clock::now();
  cpu_start = cpu_seconds();
  const auto webm = fapc::face::encode_webm(track, fapc::face::VideoOptions{}, nullptr, "bench.webm");
  const double webm_seconds = seconds_since(start);
  const double webm_cpu = cpu_seconds() - cpu_start;
  if (!webm) {
    std::printf("webm: %s\n", webm.error().message.c_str());
    return 1;
  }
  std::printf("webm 640x480, 60 s animation: %.2f s CPU (%.2f s wall), %zu bytes\n", webm_cpu, webm_seconds,
              webm->size());
  // The 3D head: building the mesh and its targets once (what the first .glb of a run pays), then
  // the 60 s animation as .glb.
  cpu_start = cpu_seconds();
  const std::size_t targets = fapc::head3d::morph_targets().size();
  const double build_cpu = cpu_seconds() - cpu_start;
  start = std::chrono::steady_clock::now();
  cpu_start = cpu_seconds();
  const auto glb = fapc::head3d::head_gltf(sequence, {}, "bench.glb");
  const double glb_cpu = cpu_seconds() - cpu_start;
  const double glb_seconds = seconds_since(start);
  if (!glb) {
    std::printf("glb: %s\n", glb.error().message.c_str());
    return 1;
  }
  std::printf(
      "3D head and %zu morph targets built in %.3f s CPU; glb, 60 s animation: %.3f s CPU (%.3f s wall), "
      "%zu bytes\n",
      targets, build_cpu, glb_cpu, glb_seconds, glb->size());
  // The same with --morphs arkit: the 52 shapes' targets, and one bounded least-squares fit a frame.
  cpu_start = cpu_seconds();
  fapc::head3d::GltfOptions arkit;
  arkit.names = fapc::head3d::MorphNames::arkit;
  const auto arkit_glb = fapc::head3d::head_gltf(sequence, arkit, "bench-arkit.glb");
  const double arkit_cpu = cpu_seconds() - cpu_start;
  if (!arkit_glb) {
    std::printf("glb: %s\n", arkit_glb.error().message.c_str());
    return 1;
  }
  std::printf("glb with ARKit targets, 60 s animation: %.3f s CPU (targets built and frames fitted), %zu bytes\n",
              arkit_cpu, arkit_glb->size());
  return 0;
}

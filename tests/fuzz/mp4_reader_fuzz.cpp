// libFuzzer target: the MP4 reader and the views on top of it (scene, object descriptors, FBA
// track) must never crash or read out of bounds, and an FBA track they accept must survive the
// writer: written again and read back, it is the same track.
#include <cstdint>
#include <cstdlib>

#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fapc::mpeg4;
  auto mp4 = read_mp4(Bytes(data, data + size), "fuzz.mp4");
  if (!mp4.ok()) return 0;
  (void)read_scene(*mp4);
  (void)read_object_descriptors(*mp4);
  auto track = read_fba_track(*mp4);
  if (!track.ok() || !check_fba_track(*track).ok()) return 0;
  auto again = write_mp4(*track);
  if (!again.ok()) std::abort();
  auto reread = read_mp4(*again, "again.mp4");
  if (!reread.ok()) std::abort();
  auto back = read_fba_track(*reread);
  if (!back.ok() || !(*back == *track)) std::abort();
  auto scene = read_scene(*reread);
  if (!scene.ok() || !(scene->scene == face_scene())) std::abort();
  return 0;
}

// libFuzzer target: the whole command pipeline of `fapc compile`, input bytes of any kind to every
// output kind. The first byte picks the input kind (by its extension, through fapc::pipeline's
// reader table), the second the options (frame rate, --duration, quantiser), the rest is the file.
// Loading and writing must never crash, hang or exhaust memory; every load error must be placed
// in the input; what is written as .fap or .fba must read back.
//
// The input is written to a private temporary folder because the front ends read paths (and
// resolve their includes from them): a .combine or XMT-Omega document naming itself exercises the
// cycle checks, one naming another kind of file the include policy.
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>

#include "diagnostic_checks.hpp"
#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/engine.hpp"

namespace {

constexpr std::array<const char*, 8> kInputExtensions = {".fap",   ".fap.gz", ".fba", ".mp4",
                                                         ".mimic", ".fml",    ".xmt", ".combine"};
// Writing is linear in the frames; past this the fuzzer would spend its time encoding and drawing
// faces (the picture and video writers: about a millisecond a frame under the sanitizers, so a
// 36-byte script of 10^4 frames took past the 10 s a fuzzer allows an input).
constexpr std::size_t kMaxFramesWritten = 2000;
// Loading is too, and under the sanitizers a million frames (the default limit: a 36-byte Mimic
// script holding a value for 10^4 s at 100 fps) take past the 10 s a fuzzer allows an input. A
// lower limit keeps inputs quick and sends the long ones through the limit's checks instead.
constexpr std::int64_t kMaxFramesLoaded = std::int64_t{1} << 17;

std::filesystem::path folder_of_this_process() {
  return std::filesystem::temp_directory_path() / ("fapc-pipeline-fuzz-" + std::to_string(::getpid()));
}

void remove_work_folder() {
  std::error_code ignored;
  std::filesystem::remove_all(folder_of_this_process(), ignored);
}

const std::filesystem::path& work_folder() {
  static const std::filesystem::path folder = [] {
    std::atexit(remove_work_folder);
    return folder_of_this_process();
  }();
  return folder;
}

fapc::pipeline::ConvertOptions options_from(std::uint8_t bits) {
  fapc::pipeline::ConvertOptions options;
  constexpr std::array<int, 4> kRates = {25, 10, 30, 100};
  options.fps = kRates[bits & 3];
  options.limits.max_frames = kMaxFramesLoaded;
  if (bits & 4) options.duration = 5;
  options.quant = 1 + ((bits >> 3) & 7);
  if (bits & 0x40) options.events["e"] = "1";
  return options;
}

// What a writer produced must be readable by the matching reader.
void check_written(const std::string& kind, const std::string& bytes) {
  if (kind == "fap") {
    if (!fapc::read_fap_text(bytes, "out.fap")) std::abort();
  } else if (kind == "fba") {
    fapc::FbaDecodeOptions decode;
    decode.file = "out.fba";
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    if (!fapc::decode_fba(std::span<const std::uint8_t>(data, bytes.size()), decode)) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

// Before the first input: one short script through every writer, so that what a writer builds
// once per process (the 3D head's mesh and morph targets, fonts, codecs: seconds under the
// sanitizers) is not charged to whichever input comes first, against libFuzzer's timeout.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Before libFuzzer's own threads (its memory watch): fapc/speech/engine.hpp.
  fapc::speech::start_engine_process();
  const std::string warm = std::string("\x04\x00") + "main { jaw <hold=0.1,value=0.1>; }\n";  // .mimic, 25 fps
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(warm.data()), warm.size());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::string extension = kInputExtensions[data[0] % kInputExtensions.size()];
  const fapc::pipeline::ConvertOptions options = options_from(data[1]);
  // A fresh folder for every input: what one run left must not change the next one.
  std::filesystem::remove_all(work_folder());
  std::filesystem::create_directories(work_folder());
  const std::string input = (work_folder() / ("in" + extension)).string();
  {
    std::ofstream out(input, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 2), static_cast<std::streamsize>(size - 2));
  }
  auto loaded = fapc::pipeline::load(input, options);
  if (!loaded) {
    fapc::fuzz::require_placed(loaded.error());
    return 0;
  }
  if (loaded->frames.frames.size() > kMaxFramesWritten) return 0;
  // Every writer of the table, so a writer added later is fuzzed too; but .gltf, the .glb row's
  // model written out by tinygltf as JSON with the buffers in base64 text: a character at a time,
  // seconds per input under the sanitizers (a seed took 11 to 13 s on a busy machine, past
  // libFuzzer's 10 s). The model itself is fuzzed through .glb.
  for (const fapc::pipeline::OutputFormat& format : fapc::pipeline::formats().outputs()) {
    if (format.kind == "gltf") continue;
    const std::string path = (work_folder() / ("out" + format.extensions.front())).string();
    auto bytes = format.write(*loaded, path, options);
    if (!bytes) {
      if (bytes.error().where.file.empty()) fapc::fuzz::require_placed(bytes.error());
      continue;
    }
    check_written(format.kind, *bytes);
  }
  return 0;
}

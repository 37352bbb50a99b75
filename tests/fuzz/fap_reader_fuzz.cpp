// libFuzzer target: the .fap reader must never crash, and whatever it accepts must survive the
// writer and read back to the same frames.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fapc/codec/fap_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto read = fapc::read_fap_text(text, "fuzz.fap");
  if (!read.ok()) return 0;
  const auto& frames = read->sequence.frames;
  // Gap filling in the writer could blow up on huge frame-number jumps; keep the check bounded.
  // (The span is computed without overflow: frame numbers may be anywhere in int64.)
  std::int64_t span = 0;
  if (!frames.empty() &&
      (__builtin_sub_overflow(frames.back().number, frames.front().number, &span) || span > 100000 || span < -100000))
    return 0;
  auto again = fapc::read_fap_text(fapc::write_fap_text(read->sequence), "again.fap");
  if (!again.ok()) std::abort();
  return 0;
}

// The FBA codec on the 8 Xface emotion files (issue 4, fba-bitstream.md 12.4): bits per frame at
// fap_quant 1, 2 and 4 with fitted ranges, the largest absolute error, the order-0 entropy of
// the coded symbols (a lower bound for the arithmetic-coded payload), and encode and decode
// speed in memory on one core. Prints a table; not a test.
//
//   build/bin/fba_codec_bench [seconds per measurement, default 0.3]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <string>
#include <vector>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/codec/file_io.hpp"

namespace {

constexpr const char* kFiles[] = {"anger", "beg", "disgust", "fear", "happy-for", "hate", "joy", "pride"};
constexpr int kQuants[] = {1, 2, 4};
constexpr std::size_t kQuantCount = std::size(kQuants);

struct Row {
  std::string name;
  std::size_t frames = 0;
  std::size_t intra = 0;                     // intra planes at fap_quant 1
  double bits[kQuantCount] = {};             // bits per frame
  std::int64_t max_error[kQuantCount] = {};  // largest |decoded - input|
  double entropy = 0;                        // order-0 bound at fap_quant 1, bits per frame
  double encode_fps = 0;
  double decode_fps = 0;
};

[[noreturn]] void fail(const std::string& what, const fapc::Diagnostic& d) {
  std::fprintf(stderr, "%s: %s\n", what.c_str(), fapc::format_diagnostic(d).c_str());
  std::exit(1);
}

fapc::FapSequence load(const std::string& name) {
  const std::string path = std::string(FAPC_SOURCE_DIR) + "/corpus/fap/bestdpf__xface-new/" + name + ".fap";
  auto text = fapc::read_file_bytes(path);
  if (!text) fail(path, text.error());
  auto read = fapc::read_fap_text(*text, path);
  if (!read) fail(path, read.error());
  return std::move(read->sequence);
}

std::int64_t max_error(const fapc::FapSequence& in, const fapc::FapSequence& out) {
  std::int64_t worst = 0;
  for (std::size_t k = 0; k < in.frames.size(); ++k)
    for (int fap = 3; fap <= fapc::kFapCount; ++fap)
      if (in.frames[k].has(fap))
        worst = std::max<std::int64_t>(worst, std::llabs(std::int64_t{in.frames[k].value(fap)} - out.frames[k].value(fap)));
  return worst;
}

double entropy_bits(const std::map<std::int64_t, std::size_t>& counts) {
  std::size_t n = 0;
  for (const auto& [symbol, count] : counts) n += count;
  double bits = 0;
  for (const auto& [symbol, count] : counts)
    bits -= static_cast<double>(count) * std::log2(static_cast<double>(count) / static_cast<double>(n));
  return bits;
}

// The symbols the coder carried, recovered from the decoded frames: per FAP, its quantised value
// in intra planes and its quantised difference from the previous frame in predictive planes,
// each kind with its own model, as in the stream. Returns the sum of their order-0 entropies.
double order0_bits(const fapc::DecodedFba& decoded, int quant) {
  const auto& frames = decoded.sequence.frames;
  std::vector<bool> intra(frames.size(), false);
  for (const fapc::FbaIntraPlane& plane : decoded.info.intra_planes)
    for (std::size_t k = 0; k < frames.size(); ++k)
      if (frames[k].number == plane.frame) intra[k] = true;
  std::map<std::int64_t, std::size_t> intra_counts[fapc::kFapCount], pred_counts[fapc::kFapCount];
  for (std::size_t k = 0; k < frames.size(); ++k)
    for (int fap = 3; fap <= fapc::kFapCount; ++fap) {
      if (!frames[k].has(fap)) continue;
      const auto i = static_cast<std::size_t>(fap - 1);
      const std::int64_t step = std::max<std::int64_t>(fapc::fap_table()[i].quant_step * quant, 1);
      if (intra[k]) {
        ++intra_counts[i][frames[k].value(fap) / step];
      } else {
        ++pred_counts[i][(std::int64_t{frames[k].value(fap)} - frames[k - 1].value(fap)) / step];
      }
    }
  double bits = 0;
  for (std::size_t i = 0; i < fapc::kFapCount; ++i) bits += entropy_bits(intra_counts[i]) + entropy_bits(pred_counts[i]);
  return bits;
}

// CPU time of this thread: what one core spends, whatever else the machine runs.
double thread_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

// Runs `work` (which handles `frames` frames) repeatedly for at least `seconds` of CPU time,
// three times; the best rate in frames per second.
template <class Work>
double frames_per_second(std::size_t frames, double seconds, Work&& work) {
  double best = 0;
  for (int round = 0; round < 3; ++round) {
    const double start = thread_seconds();
    std::size_t runs = 0;
    double elapsed = 0;
    do {
      work();
      ++runs;
      elapsed = thread_seconds() - start;
    } while (elapsed < seconds);
    best = std::max(best, static_cast<double>(frames * runs) / elapsed);
  }
  return best;
}

Row measure(const std::string& name, double seconds) {
  Row row;
  row.name = name;
  const fapc::FapSequence input = load(name);
  row.frames = input.frames.size();
  const double frames = static_cast<double>(input.frames.back().number - input.frames.front().number + 1);
  for (std::size_t q = 0; q < kQuantCount; ++q) {
    fapc::FbaEncodeOptions options;
    options.quant = kQuants[q];
    auto encoded = fapc::encode_fba(input, options);
    if (!encoded) fail(name, encoded.error());
    if (auto verified = fapc::verify_fba(input, *encoded, options, name); !verified) fail(name, verified.error());
    auto decoded = fapc::decode_fba(encoded->bytes);
    if (!decoded) fail(name, decoded.error());
    row.bits[q] = 8.0 * static_cast<double>(encoded->bytes.size()) / frames;
    row.max_error[q] = max_error(input, decoded->sequence);
    if (kQuants[q] != 1) continue;
    row.intra = decoded->info.intra_planes.size();
    row.entropy = order0_bits(*decoded, kQuants[q]) / frames;
    const std::vector<std::uint8_t> bytes = encoded->bytes;
    row.encode_fps = frames_per_second(row.frames, seconds, [&] {
      auto again = fapc::encode_fba(input, options);
      if (!again || again->bytes.size() != bytes.size()) std::abort();
    });
    row.decode_fps = frames_per_second(row.frames, seconds, [&] {
      auto again = fapc::decode_fba(bytes);
      if (!again || again->sequence.frames.size() != row.frames) std::abort();
    });
  }
  return row;
}

void print(const Row& r) {
  std::printf("%-10s %6zu %5zu  %7.1f %7.1f %7.1f  %5lld %5lld %5lld  %8.1f  %9.0f %9.0f\n", r.name.c_str(), r.frames,
              r.intra, r.bits[0], r.bits[1], r.bits[2], static_cast<long long>(r.max_error[0]),
              static_cast<long long>(r.max_error[1]), static_cast<long long>(r.max_error[2]), r.entropy,
              r.encode_fps, r.decode_fps);
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 0.3;
  std::printf("FBA codec, Xface emotion files, fitted ranges; bits/frame include start, stuffing and end codes.\n");
  std::printf("entropy: order-0 entropy of the coded symbols at fap_quant 1 (per FAP, intra and predictive\n");
  std::printf("models apart), a lower bound for the arithmetic-coded part. Speeds in memory, in CPU time of one core.\n\n");
  std::printf("%-10s %6s %5s  %7s %7s %7s  %5s %5s %5s  %8s  %9s %9s\n", "file", "frames", "intra", "bits q1", "q2",
              "q4", "err1", "err2", "err4", "entropy", "enc fps", "dec fps");
  Row mean;
  mean.name = "average";
  for (const char* name : kFiles) {
    const Row row = measure(name, seconds);
    print(row);
    mean.frames += row.frames;
    mean.intra += row.intra;
    for (std::size_t q = 0; q < kQuantCount; ++q) {
      mean.bits[q] += row.bits[q] / std::size(kFiles);
      mean.max_error[q] = std::max(mean.max_error[q], row.max_error[q]);
    }
    mean.entropy += row.entropy / std::size(kFiles);
    mean.encode_fps += row.encode_fps / std::size(kFiles);
    mean.decode_fps += row.decode_fps / std::size(kFiles);
  }
  print(mean);
  std::printf("\n(average row: frames and intra planes are totals, errors the largest, the rest means of the files)\n");
  return 0;
}

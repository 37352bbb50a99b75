// The FBA codec on the 8 Xface emotion files (docs/fba.md section 5, docs/fba-bitstream.md
// section 12.4): bits per frame at fap_quant 1, 2 and 4 with fitted ranges, the largest absolute
// error, the order-0 entropy of the coded symbols (a lower bound for the arithmetic-coded payload),
// and encode and decode speed in memory on one core. Prints a table; not a test.
//
//   build/bin/fba_codec_bench [seconds per measurement round, default 0.1]
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

using Counts = std::map<std::int64_t, std::size_t>;

double entropy_bits(const Counts& counts) {
  std::size_t n = 0;
  for (const auto& [symbol, count] : counts) n += count;
  double bits = 0;
  for (const auto& [symbol, count] : counts)
    bits -= static_cast<double>(count) * std::log2(static_cast<double>(count) / static_cast<double>(n));
  return bits;
}

// What the decoder's adaptive model (docs/fba-bitstream.md section 6.2: every count starts at 1 and
// grows by 1) costs for these symbols over an alphabet of A symbols: log2 of (N + A - 1)! /
// ((A - 1)! prod n_i!), ignoring the coder's rounding. Its excess over N times the entropy is the
// price of learning the distribution from a flat start.
double adaptive_bits(const Counts& counts, double symbols) {
  double n = 0, log_e = -std::lgamma(symbols);
  for (const auto& [symbol, count] : counts) {
    n += static_cast<double>(count);
    log_e -= std::lgamma(static_cast<double>(count) + 1);
  }
  return (log_e + std::lgamma(n + symbols)) / std::log(2.0);
}

// The smallest alphabet the range lists can give for predictive symbols from `low` to `high`
// (docs/fba-bitstream.md section 5.6: each side a multiple of 60, divided by fap_quant).
double fitted_alphabet(std::int64_t low, std::int64_t high, int quant) {
  const std::int64_t s = std::max(quant, 1);
  const auto side = [s](std::int64_t m) { return (m * s + 59) / 60 * 60 / s; };
  return static_cast<double>(side(std::max<std::int64_t>(high, 0)) + side(std::max<std::int64_t>(-low, 0)) + 1);
}

struct SymbolCost {
  double entropy = 0;   // order-0, each FAP's intra and predictive symbols apart, whole file
  double adaptive = 0;  // predictive symbols through fresh adaptive models, group by group
};

// The symbols the coder carried, recovered from the decoded frames: per FAP, its quantised value
// in intra planes and its quantised difference from the previous frame in predictive planes.
SymbolCost symbol_cost(const fapc::DecodedFba& decoded, int quant) {
  const auto& frames = decoded.sequence.frames;
  std::vector<bool> intra(frames.size(), false);
  for (const fapc::FbaIntraPlane& plane : decoded.info.intra_planes)
    for (std::size_t k = 0; k < frames.size(); ++k)
      if (frames[k].number == plane.frame) intra[k] = true;
  Counts intra_counts[fapc::kFapCount], pred_counts[fapc::kFapCount], group[fapc::kFapCount];
  SymbolCost cost;
  const auto close_group = [&] {
    for (Counts& counts : group) {
      if (counts.empty()) continue;
      cost.adaptive += adaptive_bits(counts, fitted_alphabet(counts.begin()->first, counts.rbegin()->first, quant));
      counts.clear();
    }
  };
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (intra[k]) close_group();
    for (int fap = 3; fap <= fapc::kFapCount; ++fap) {
      if (!frames[k].has(fap)) continue;
      const auto i = static_cast<std::size_t>(fap - 1);
      const std::int64_t step = std::max<std::int64_t>(fapc::fap_table()[i].quant_step * quant, 1);
      if (intra[k]) {
        ++intra_counts[i][frames[k].value(fap) / step];
      } else {
        const std::int64_t q = (std::int64_t{frames[k].value(fap)} - frames[k - 1].value(fap)) / step;
        ++pred_counts[i][q];
        ++group[i][q];
      }
    }
  }
  close_group();
  for (std::size_t i = 0; i < fapc::kFapCount; ++i)
    cost.entropy += entropy_bits(intra_counts[i]) + entropy_bits(pred_counts[i]);
  return cost;
}

struct Row {
  std::string name;
  std::size_t frames = 0;
  std::size_t intra = 0;                     // intra planes at fap_quant 1
  double bits[kQuantCount] = {};             // bits per frame
  double kept_bits = 0;                      // at fap_quant 1 with the input's masks kept
  std::int64_t max_error[kQuantCount] = {};  // largest |decoded - input|
  SymbolCost symbols;                        // at fap_quant 1, bits per frame
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

// The largest |decoded - input| over the input's FAPs; one the encoder left out at rest counts as
// decoded 0.
std::int64_t max_error(const fapc::FapSequence& in, const fapc::FapSequence& out) {
  std::int64_t worst = 0;
  for (std::size_t k = 0; k < in.frames.size(); ++k)
    for (int fap = 3; fap <= fapc::kFapCount; ++fap)
      if (in.frames[k].has(fap)) {
        const std::int64_t decoded = out.frames[k].has(fap) ? out.frames[k].value(fap) : 0;
        worst = std::max<std::int64_t>(worst, std::llabs(in.frames[k].value(fap) - decoded));
      }
  return worst;
}

// CPU time of this thread: what one core spends, whatever else the machine runs.
double thread_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

// Runs `work` (which handles `frames` frames) repeatedly for at least `seconds` of CPU time,
// seven times; the best rate in frames per second (on a shared machine the other rounds measure
// the neighbours as much as the codec).
template <class Work>
double frames_per_second(std::size_t frames, double seconds, Work&& work) {
  double best = 0;
  for (int round = 0; round < 7; ++round) {
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
    options.masks = fapc::FbaMaskMode::keep;
    auto kept = fapc::encode_fba(input, options);
    if (!kept) fail(name, kept.error());
    if (auto verified = fapc::verify_fba(input, *kept, options, name); !verified) fail(name, verified.error());
    row.kept_bits = 8.0 * static_cast<double>(kept->bytes.size()) / frames;
    options.masks = fapc::FbaMaskMode::fit;
    row.intra = decoded->info.intra_planes.size();
    row.symbols = symbol_cost(*decoded, kQuants[q]);
    row.symbols.entropy /= frames;
    row.symbols.adaptive /= frames;
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
  std::printf("%-10s %6zu %5zu  %7.1f %7.1f %7.1f %7.1f  %5lld %5lld %5lld  %7.1f %8.1f  %9.0f %9.0f\n", r.name.c_str(),
              r.frames, r.intra, r.bits[0], r.bits[1], r.bits[2], r.kept_bits, static_cast<long long>(r.max_error[0]),
              static_cast<long long>(r.max_error[1]), static_cast<long long>(r.max_error[2]), r.symbols.entropy,
              r.symbols.adaptive, r.encode_fps, r.decode_fps);
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 0.1;
  std::printf(
      "FBA codec on the Xface emotion files, fitted ranges. bits: stream bits per frame (start, stuffing\n"
      "and end codes included) at fap_quant 1, 2, 4, and at 1 with the input's masks kept (--masks keep);\n"
      "intra: intra planes at fap_quant 1; err: largest |decoded - input|. At fap_quant 1:\n"
      "entropy: order-0 entropy of the coded symbols (each FAP's intra and predictive symbols apart), a\n"
      "lower bound for the arithmetic-coded part; adaptive: what the decoder's adaptive models, starting\n"
      "flat over the fitted alphabets, cost for the predictive symbols. Speeds: frames per second in memory,\n"
      "CPU time of one core, each file coded over and over.\n\n");
  std::printf("%-10s %6s %5s  %7s %7s %7s %7s  %5s %5s %5s  %7s %8s  %9s %9s\n", "file", "frames", "intra", "bits q1",
              "q2", "q4", "keep q1", "err1", "err2", "err4", "entropy", "adaptive", "enc fps", "dec fps");
  Row mean;
  mean.name = "average";
  std::vector<fapc::FapSequence> inputs;
  std::vector<std::vector<std::uint8_t>> streams;
  for (const char* name : kFiles) {
    const Row row = measure(name, seconds);
    print(row);
    mean.frames += row.frames;
    mean.intra += row.intra;
    for (std::size_t q = 0; q < kQuantCount; ++q) {
      mean.bits[q] += row.bits[q] / std::size(kFiles);
      mean.max_error[q] = std::max(mean.max_error[q], row.max_error[q]);
    }
    mean.kept_bits += row.kept_bits / std::size(kFiles);
    mean.symbols.entropy += row.symbols.entropy / std::size(kFiles);
    mean.symbols.adaptive += row.symbols.adaptive / std::size(kFiles);
    mean.encode_fps += row.encode_fps / std::size(kFiles);
    mean.decode_fps += row.decode_fps / std::size(kFiles);
    inputs.push_back(load(name));
    streams.push_back(fapc::encode_fba(inputs.back())->bytes);
  }
  print(mean);
  std::printf("\n(average: frames and intra planes are totals, errors the largest, the rest means of the files)\n");
  // The same work with the files taken in turn, so that the processor cannot learn one file's
  // branches by heart: closer to coding each stream once.
  const double in_turn_encode = frames_per_second(mean.frames, seconds, [&] {
    for (const auto& input : inputs)
      if (!fapc::encode_fba(input)) std::abort();
  });
  const double in_turn_decode = frames_per_second(mean.frames, seconds, [&] {
    for (const auto& bytes : streams)
      if (!fapc::decode_fba(bytes)) std::abort();
  });
  std::printf("all 8 files in turn, fap_quant 1: encode %.0f, decode %.0f frames per second\n", in_turn_encode,
              in_turn_decode);
  return 0;
}

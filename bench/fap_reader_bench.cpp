// Reader throughput over the whole .fap corpus and over a long file, in MB/s of input text.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"

namespace {

std::vector<std::string> load_corpus() {
  std::vector<std::string> texts;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(FAPC_SOURCE_DIR "/corpus/fap")) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    texts.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return texts;
}

void BM_ReadCorpus(benchmark::State& state) {
  static const std::vector<std::string> texts = load_corpus();
  std::size_t bytes = 0;
  for (auto _ : state) {
    for (const std::string& text : texts) {
      auto read = fapc::read_fap_text(text, "corpus");
      benchmark::DoNotOptimize(read);
      bytes += text.size();
    }
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
  state.counters["files"] = static_cast<double>(texts.size());
}
BENCHMARK(BM_ReadCorpus)->Unit(benchmark::kMillisecond);

void BM_WriteCorpus(benchmark::State& state) {
  static const std::vector<std::string> texts = load_corpus();
  std::vector<fapc::FapSequence> sequences;
  for (const std::string& text : texts) sequences.push_back(fapc::read_fap_text(text, "c")->sequence);
  std::size_t bytes = 0;
  for (auto _ : state)
    for (const auto& s : sequences) {
      const std::string out = fapc::write_fap_text(s);
      bytes += out.size();
      benchmark::DoNotOptimize(out);
    }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_WriteCorpus)->Unit(benchmark::kMillisecond);

// A long file (issue 19: reading at the speed of the disk): the Xface emotions of the corpus,
// repeated and renumbered to 100,000 frames (some 30 MB), read from memory and from a file.
const std::string& long_text() {
  static const std::string text = [] {
    std::vector<fapc::FapFrame> real;
    for (const auto& entry : std::filesystem::directory_iterator(FAPC_SOURCE_DIR "/corpus/fap/bestdpf__xface-new")) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      const auto read = fapc::read_fap_text(file, "c");
      for (const auto& f : read->sequence.frames) real.push_back(f);
    }
    fapc::FapSequence long_sequence{"long", 25, {}};
    for (std::size_t k = 0; k < 100'000; ++k) long_sequence.frames.push_back(real[k % real.size()]);
    return fapc::write_fap_text(long_sequence);
  }();
  return text;
}

void BM_ReadLongText(benchmark::State& state) {
  const std::string& text = long_text();
  for (auto _ : state) {
    auto read = fapc::read_fap_text(text, "long.fap");
    benchmark::DoNotOptimize(read);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(text.size() * state.iterations()));
}
BENCHMARK(BM_ReadLongText)->Unit(benchmark::kMillisecond);

void BM_ReadLongFile(benchmark::State& state) {
  const std::string path = std::filesystem::temp_directory_path() / "fap_reader_bench_long.fap";
  {
    std::ofstream out(path, std::ios::binary);
    out << long_text();
  }
  for (auto _ : state) {
    auto bytes = fapc::read_file_bytes(path);
    auto read = fapc::read_fap_text(*bytes, path);
    benchmark::DoNotOptimize(read);
  }
  std::filesystem::remove(path);
  state.SetBytesProcessed(static_cast<std::int64_t>(long_text().size() * state.iterations()));
}
BENCHMARK(BM_ReadLongFile)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

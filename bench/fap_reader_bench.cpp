// Reader throughput over the whole .fap corpus, in MB/s of input text.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fapc/codec/fap_file.hpp"

namespace {

std::vector<std::string> load_corpus() {
  std::vector<std::string> texts;
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(FAPC_SOURCE_DIR "/corpus/fap")) {
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

}  // namespace

BENCHMARK_MAIN();

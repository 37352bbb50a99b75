// Time spent per second of speech (docs/speech.md, "Cost"): eSpeak NG's synthesis alone, then the
// whole load of an FML talk (synthesis, phonemes to visemes, coarticulation, scheduling,
// rendering the frames at 25 fps and mixing the audio). Prints seconds of work per second of
// speech, the best of several runs.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/engine.hpp"

namespace {

const char* const kEnglish =
    "A talking face is what most authored scripts are for. A user who writes hello, my name is Alice, "
    "expects a face that says it, in time with a voice they can hear, in the files they hand to players. "
    "The speech engine gives every phoneme with its start time, and the mouth follows them.";
const char* const kFrench =
    "Un visage qui parle est ce que la plupart des scripts veulent montrer. Celui qui écrit bonjour, "
    "je m'appelle Alice, attend un visage qui le dise, en même temps qu'une voix qu'il entend.";

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void measure(const char* language, const char* text) {
  fapc::SpeechRequest request;
  request.text = text;
  request.language = language;
  double best_synthesis = 1e9;
  double speech_seconds = 0;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const auto spoken = fapc::speech::engine()(request);
    best_synthesis = std::min(best_synthesis, seconds_since(start));
    if (!spoken) {
      std::printf("%s: %s\n", language, spoken.error().message.c_str());
      return;
    }
    speech_seconds = spoken->duration;
  }
  const auto path =
      std::filesystem::temp_directory_path() / ("fapc-speech-bench-" + std::to_string(::getpid()) + ".fml");
  std::ofstream(path) << "<fml><story><talk lang=\"" << language << "\">" << text << "</talk></story></fml>\n";
  double best_load = 1e9;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const auto loaded = fapc::pipeline::load(path.string(), fapc::pipeline::ConvertOptions{});
    best_load = std::min(best_load, seconds_since(start));
    if (!loaded) {
      std::printf("%s: %s\n", language, loaded.error().message.c_str());
      return;
    }
  }
  std::filesystem::remove(path);
  std::printf("%-3s %.2f s of speech: synthesis %.4f s/s, synthesis + lowering + frames + audio mix %.4f s/s\n",
              language, speech_seconds, best_synthesis / speech_seconds, best_load / speech_seconds);
}

}  // namespace

// `speech_bench --phonemes LANGUAGE TEXT`: the engine's phonemes of TEXT, one per line (name,
// begin, end, viseme), for docs/speech/plot.py.
int print_phonemes(const char* language, const char* text) {
  fapc::SpeechRequest request;
  request.text = text;
  request.language = language;
  const auto spoken = fapc::speech::engine()(request);
  if (!spoken) {
    std::fprintf(stderr, "%s\n", spoken.error().message.c_str());
    return 1;
  }
  for (const fapc::SpokenPhoneme& p : spoken->phonemes)
    std::printf("%s %.4f %.4f %d\n", p.name.c_str(), p.begin, p.end, p.viseme);
  return 0;
}

int main(int argc, char** argv) {
  if (!fapc::speech::available()) {
    std::printf("built without the speech engine\n");
    return 0;
  }
  if (argc == 4 && std::string(argv[1]) == "--phonemes") return print_phonemes(argv[2], argv[3]);
  std::printf("%s\n", fapc::speech::engine_name().c_str());
  measure("en", kEnglish);
  measure("fr", kFrench);
  return 0;
}

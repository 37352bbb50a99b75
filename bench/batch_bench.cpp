// The batch bench: `fapc batch` over 1,000 inputs made from corpus/examples at run time (copies of
// the whole examples tree, so relative includes and operands still resolve), to every output
// kind that every input has (all but .timeline, which needs a script input), at --jobs 1 and
// --jobs 2. Prints files/s for each and the ratio, and checks that the two output trees are
// byte for byte the same. Then what a cluster user pays for, per node (docs/cluster.md): files per
// second and per core for one array task using every core and for 4 array tasks (shards) at once,
// on the same inputs and on speech-heavy ones (FML talk to MP4: voice, AAC, mouth), and the AAC
// stage with libavcodec's two coders (twoloop, its default, and fast, fapc's) on the same voice,
// with the quality of each (signal-to-noise ratio against the voice encoded).
// Usage: batch_bench [FAPC_PROGRAM] [FILES] [SPEECH_FILES]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "fapc/audio_codec/aac.hpp"
#include "fapc/transcoder/wav.hpp"

namespace fs = std::filesystem;
namespace audio = fapc::audio;
using fapc::AudioTrack;
using fapc::Result;

namespace {

const char* kKinds = "fap,json,fba,mp4,svg,xmt,xmt-bifs";

bool is_input(const fs::path& p) {
  for (const char* ext : {".fap", ".fba", ".mp4", ".mimic", ".mim", ".fml", ".xmt", ".combine"})
    if (p.extension() == ext) return true;
  return false;
}

std::size_t inputs_under(const fs::path& folder) {
  std::size_t count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    count += entry.is_regular_file() && is_input(entry.path());
  return count;
}

// Whole copies of the examples tree (their includes and operands resolve inside each copy) while
// they fit, then single inputs up to `wanted`, beside the other files of their folder (the
// expressions and phoneme files they include).
std::size_t make_inputs(const fs::path& examples, const fs::path& into, std::size_t wanted) {
  const std::size_t per_copy = inputs_under(examples);
  std::size_t made = 0;
  for (int copy = 0; made + per_copy <= wanted; ++copy, made += per_copy)
    fs::copy(examples, into / ("copy" + std::to_string(copy)), fs::copy_options::recursive);
  std::vector<fs::path> standalone;
  fs::create_directories(into / "rest");
  for (const char* folder : {"fap", "fml", "mimic"})
    for (const auto& entry : fs::directory_iterator(examples / folder)) {
      if (is_input(entry.path()))
        standalone.push_back(entry.path());
      else if (entry.is_regular_file())
        fs::copy_file(entry.path(), into / "rest" / entry.path().filename());
    }
  std::sort(standalone.begin(), standalone.end());
  for (std::size_t k = 0; made < wanted && k < standalone.size(); ++k, ++made)
    fs::copy_file(standalone[k], into / "rest" / standalone[k].filename());
  return made;
}

struct Timing {
  double wall = 0;  // seconds
  double cpu = 0;   // user + system seconds of the fapc process
};

double cpu_of_children() {
  rusage usage{};
  ::getrusage(RUSAGE_CHILDREN, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

// Runs a shell command line, timed; exits when it fails (its output is in `log`).
Timing timed(const std::string& command, const fs::path& log) {
  const double cpu_before = cpu_of_children();
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) {
    std::cerr << "batch_bench: `" << command << "` failed (status " << WEXITSTATUS(status) << "), see " << log << "\n";
    std::exit(1);
  }
  return Timing{seconds, cpu_of_children() - cpu_before};
}

std::string batch_command(const std::string& fapc, const fs::path& in, const fs::path& out, const std::string& kinds,
                          const std::string& options, const std::string& log) {
  return "'" + fapc + "' batch '" + in.string() + "' -o '" + out.string() + "' --to " + kinds + " " + options + " > '" +
         log + "' 2>&1";
}

Timing run(const std::string& fapc, const fs::path& in, const fs::path& out, int jobs) {
  return timed(batch_command(fapc, in, out, kKinds, "--jobs " + std::to_string(jobs), out.string() + ".log"),
               out.string() + ".log");
}

// A node running the batch as `tasks` array tasks at once, each its shard with cores/tasks jobs
// (at least one), into one output folder, as Slurm would place them.
Timing run_tasks(const std::string& fapc, const fs::path& in, const fs::path& out, const std::string& kinds, int tasks,
                 int cores) {
  const int jobs = std::max(1, cores / tasks);
  std::string line = "(";
  for (int t = 0; t < tasks; ++t)
    line +=
        batch_command(fapc, in, out, kinds,
                      "--jobs " + std::to_string(jobs) + " --shard " + std::to_string(t) + "/" + std::to_string(tasks) +
                          " --report-json '" + out.string() + "-" + std::to_string(t) + ".json'",
                      out.string() + "-" + std::to_string(t) + ".log") +
        " & ";
  // Every task must succeed: the merge of their reports says so (status 0 only when complete).
  line +=
      "wait) && '" + fapc + "' batch-report merge '" + out.string() + "'-*.json > '" + out.string() + ".merge' 2>&1";
  return timed(line, out.string() + ".merge");
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The first difference between two output trees, or empty.
std::string difference(const fs::path& a, const fs::path& b) {
  // The completion records (docs/cluster.md) hold times, which differ from run to run: not outputs.
  const auto record = [](const fs::path& p) { return p.string().find("/.fapc-batch/") != std::string::npos; };
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    if (!entry.is_regular_file() || record(entry.path())) continue;
    ++files;
    const fs::path other = b / fs::relative(entry.path(), a);
    if (!fs::exists(other)) return other.string() + " is missing";
    if (bytes_of(entry.path()) != bytes_of(other)) return entry.path().string() + " differs from " + other.string();
  }
  std::size_t other_files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(b))
    other_files += entry.is_regular_file() && !record(entry.path());
  if (files != other_files) return std::to_string(other_files) + " files against " + std::to_string(files);
  return {};
}

// Mean squared error of `decoded` against `original`, as a signal-to-noise ratio in dB.
double snr_db(const std::vector<std::int16_t>& original, const std::vector<std::int16_t>& decoded) {
  double signal = 0, noise = 0;
  for (std::size_t i = 0; i < original.size() && i < decoded.size(); ++i) {
    signal += double(original[i]) * original[i];
    noise += (double(original[i]) - decoded[i]) * (double(original[i]) - decoded[i]);
  }
  return 10 * std::log10(signal / std::max(noise, 1.0));
}

// The per-node figures (see the top of this file).
int per_node(const std::string& fapc, const fs::path& work, std::size_t files, std::size_t speech_files) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // Per node: files over wall time, as loaded as this machine is. Per core: files over the CPU
  // seconds they took, which other work on the machine does not change.
  const auto figures = [&](const char* what, std::size_t n, const Timing& t) {
    std::printf("%-34s %6.2f s, %6.1f files/s per node, %6.1f files per CPU second (%.2f CPU s)\n", what, t.wall,
                double(n) / t.wall, double(n) / t.cpu, t.cpu);
  };
  std::printf("per node (%d cores): %zu inputs, outputs %s\n", cores, files, kKinds);
  const Timing one = run_tasks(fapc, work / "in", work / "node1", kKinds, 1, cores);
  const Timing four = run_tasks(fapc, work / "in", work / "node4", kKinds, 4, cores);
  figures("  1 array task (--jobs all cores):", files, one);
  figures("  4 array tasks (--shard I/4):", files, four);
  const std::string differs = difference(work / "node1", work / "node4");
  std::cout << (differs.empty() ? "  outputs of 1 and 4 tasks: identical\n" : "  outputs differ: " + differs + "\n");

  // Speech-heavy: FML talk to MP4 (the voice through eSpeak NG, AAC, the mouth).
  const fs::path speech = work / "speech";
  fs::create_directories(speech);
  const fs::path talk = fs::path(FAPC_SOURCE_DIR) / "corpus/examples/fml/two-languages.fml";
  for (std::size_t k = 0; k < speech_files; ++k) fs::copy_file(talk, speech / ("talk" + std::to_string(k) + ".fml"));
  const Timing talk1 = run_tasks(fapc, speech, work / "speech1", "mp4", 1, cores);
  const Timing talk4 = run_tasks(fapc, speech, work / "speech4", "mp4", 4, cores);
  std::printf("speech-heavy: %zu copies of two-languages.fml to .mp4\n", speech_files);
  figures("  1 array task:", speech_files, talk1);
  figures("  4 array tasks:", speech_files, talk4);
  const std::string speech_differs = difference(work / "speech1", work / "speech4");
  std::cout << (speech_differs.empty() ? "  outputs of 1 and 4 tasks: identical\n"
                                       : "  outputs differ: " + speech_differs + "\n");

  // The AAC stage alone, both coders, on the same voice.
  const fs::path wav = work / "talk.wav";
  timed("'" + fapc + "' compile '" + talk.string() + "' -o '" + wav.string() + "' > '" + wav.string() + ".log' 2>&1",
        wav.string() + ".log");
  auto clip = fapc::read_wav(bytes_of(wav), wav.string());
  if (!clip) {
    std::cerr << "batch_bench: " << clip.error().message << "\n";
    return 1;
  }
  AudioTrack voice;
  voice.sample_rate = clip->sample_rate;
  voice.samples = clip->samples;
  std::printf("AAC of the voice (%.1f s at %d Hz), each coder 5 times:\n", voice.duration(), voice.sample_rate);
  double per_file[2] = {0, 0};
  int status = 0;
  const auto cpu_of_this_process = [] {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
  };
  for (const auto coder : {audio::AacCoder::twoloop, audio::AacCoder::fast}) {
    const double start = cpu_of_this_process();
    Result<audio::AacStream> aac = audio::encode_aac(voice, "talk.mp4", 64000, 0, coder);
    for (int repeat = 1; aac && repeat < 5; ++repeat) aac = audio::encode_aac(voice, "talk.mp4", 64000, 0, coder);
    const double seconds = (cpu_of_this_process() - start) / 5;  // CPU seconds per file
    auto decoded = aac ? audio::decode_aac(*aac, "talk.mp4") : Result<std::vector<std::int16_t>>(aac.error());
    if (!decoded) {
      std::cerr << "batch_bench: " << decoded.error().message << "\n";
      return 1;
    }
    const double snr = snr_db(voice.samples, *decoded);
    const bool fast = coder == audio::AacCoder::fast;
    per_file[fast] = seconds;
    std::size_t bytes = 0;
    for (const auto& frame : aac->frames) bytes += frame.size();
    std::printf("  %-8s %7.1f CPU ms per file, %6zu bytes, SNR %.1f dB, decoded length %s\n", fast ? "fast" : "twoloop",
                seconds * 1000, bytes, snr, decoded->size() == voice.samples.size() ? "exact" : "WRONG");
    if (decoded->size() != voice.samples.size() || snr < 10) status = 1;  // not speech any more
  }
  // The speech batch before (twoloop) and after (fast): the same run, the AAC stage's difference
  // added back to the CPU time of the files.
  const double before_cpu = talk1.cpu + double(speech_files) * (per_file[0] - per_file[1]);
  std::printf("speech files per second per core: %.2f with twoloop (before), %.2f with fast (after): %.2fx\n",
              double(speech_files) / before_cpu, double(speech_files) / talk1.cpu, before_cpu / talk1.cpu);
  // What a task pays once, before its first file: starting the program (libraries loaded).
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < 10; ++k) timed("'" + fapc + "' --version > /dev/null", "/dev/null");
  std::printf("process start (fapc --version): %.1f ms, paid once per array task\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 100);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string fapc = argc > 1 ? argv[1] : (fs::path(argv[0]).parent_path() / "fapc").string();
  const std::size_t wanted = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 1000;
  const std::size_t speech_files = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 16;
  const fs::path work = fs::temp_directory_path() / ("fapc-batch-bench-" + std::to_string(::getpid()));
  fs::create_directories(work / "in");
  const std::size_t files = make_inputs(fs::path(FAPC_SOURCE_DIR) / "corpus/examples", work / "in", wanted);
  std::cout << "batch bench: " << files << " inputs from corpus/examples, outputs " << kKinds << "\n" << std::flush;
  run(fapc, work / "in", work / "warm-up", 2);  // page cache and first-touch costs out of the way
  const Timing one = run(fapc, work / "in", work / "out1", 1);
  const Timing two = run(fapc, work / "in", work / "out2", 2);
  // CPU seconds show the work is the same at both settings; CPU / wall is how many cores the
  // machine actually gave (below 2 at --jobs 2 means other work held the CPUs).
  for (const auto& [jobs, t] : {std::pair{1, one}, std::pair{2, two}})
    std::printf("--jobs %d: %.2f s, %.1f files/s (%.2f CPU s, %.2f cores used)\n", jobs, t.wall,
                static_cast<double>(files) / t.wall, t.cpu, t.cpu / t.wall);
  std::printf("speed-up: %.2fx\n", one.wall / two.wall);
  const std::string differs = difference(work / "out1", work / "out2");
  std::cout << (differs.empty() ? "outputs: identical\n" : "outputs differ: " + differs + "\n");
  const int node = per_node(fapc, work, files, speech_files);
  fs::remove_all(work);
  return differs.empty() && node == 0 ? 0 : 1;
}

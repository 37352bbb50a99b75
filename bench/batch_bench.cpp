// The batch bench: `fapc batch` over 1,000 inputs made from corpus/examples at run time (copies of
// the whole examples tree, so relative includes and operands still resolve), to every output
// kind that every input has (all but .timeline, which needs a script input), at --jobs 1 and
// --jobs 2. Prints files/s for each and the ratio, and checks that the two output trees are
// byte for byte the same. Usage: batch_bench [FAPC_PROGRAM] [FILES]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const char* kKinds = "fap,json,fba,mp4,svg,xmt,xmt-bifs";

bool is_input(const fs::path& p) {
  for (const char* ext : {".fap", ".fba", ".mp4", ".mimic", ".mim", ".fml", ".xmt", ".combine"})
    if (p.extension() == ext) return true;
  return false;
}

std::size_t inputs_under(const fs::path& folder) {
  std::size_t count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) count += entry.is_regular_file() && is_input(entry.path());
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
      if (is_input(entry.path())) standalone.push_back(entry.path());
      else if (entry.is_regular_file()) fs::copy_file(entry.path(), into / "rest" / entry.path().filename());
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

Timing run(const std::string& fapc, const fs::path& in, const fs::path& out, int jobs) {
  const std::string command = "'" + fapc + "' batch '" + in.string() + "' -o '" + out.string() + "' --to " + kKinds +
                              " --jobs " + std::to_string(jobs) + " > '" + out.string() + ".log' 2>&1";
  const double cpu_before = cpu_of_children();
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) {
    std::cerr << "batch_bench: `" << command << "` failed (status " << WEXITSTATUS(status) << "), see " << out
              << ".log\n";
    std::exit(1);
  }
  return Timing{seconds, cpu_of_children() - cpu_before};
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The first difference between two output trees, or empty.
std::string difference(const fs::path& a, const fs::path& b) {
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    if (!entry.is_regular_file()) continue;
    ++files;
    const fs::path other = b / fs::relative(entry.path(), a);
    if (!fs::exists(other)) return other.string() + " is missing";
    if (bytes_of(entry.path()) != bytes_of(other)) return entry.path().string() + " differs from " + other.string();
  }
  std::size_t other_files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(b)) other_files += entry.is_regular_file();
  if (files != other_files) return std::to_string(other_files) + " files against " + std::to_string(files);
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string fapc = argc > 1 ? argv[1] : (fs::path(argv[0]).parent_path() / "fapc").string();
  const std::size_t wanted = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 1000;
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
  fs::remove_all(work);
  return differs.empty() ? 0 : 1;
}

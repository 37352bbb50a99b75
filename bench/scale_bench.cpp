// The scale bench (issue 19): how time and peak memory grow with the size of the input, for every
// kind of work fapc does on long inputs. Each case runs in a child process of its own (fork), so
// its peak memory (ru_maxrss) is its own; inputs are generated at run time, deterministically,
// into a temporary folder (no stored files), also each in a child. Prints one line per case and
// size, then the growth exponent fitted between the sizes (time ~ size^k; k near 1 is linear).
// Not a test: it prints figures. Usage: scale_bench [--max N] [--only SUBSTRING] [--folder DIR]
// (--folder keeps the generated inputs there, and uses those already there, between runs).
#include <malloc.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/pipeline.hpp"
#include "fapc/transcoder/render.hpp"

// The script generators come from issue 19a; until they are in the tree the bench measures the
// frame inputs and outputs only.
#if __has_include("script_generators.hpp")
#include "script_generators.hpp"
#define FAPC_SCALE_SCRIPTS 1
#endif

namespace fs = std::filesystem;
namespace fp = fapc::pipeline;

namespace {

struct Measure {
  bool ok = false;
  double seconds = 0;      // of the timed part, measured in the child
  double peak_mb = 0;      // the child's peak resident memory
  double cpu_seconds = 0;  // the child's CPU time, user and system, untimed parts included
  std::string note;        // the child's error, if any
};

// Runs `work` in a child process; `work` returns the seconds of its timed part (negative: failed,
// with a message on the pipe's second line).
Measure in_child(const std::function<double(std::string&)>& work) {
  int pipe_fd[2];
  if (::pipe(pipe_fd) != 0) std::abort();
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipe_fd[0]);
    std::string note;
    const double seconds = work(note);
    const std::string text = std::to_string(seconds) + "\n" + note;
    if (::write(pipe_fd[1], text.data(), text.size()) < 0) _exit(2);
    _exit(0);
  }
  ::close(pipe_fd[1]);
  std::string text;
  char buffer[4096];
  for (ssize_t got; (got = ::read(pipe_fd[0], buffer, sizeof buffer)) > 0;)
    text.append(buffer, static_cast<std::size_t>(got));
  ::close(pipe_fd[0]);
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  Measure m;
  m.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  const auto seconds_of = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6;
  };
  m.cpu_seconds = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
  if (!WIFEXITED(status) || text.empty()) {
    m.note = "child died";
    return m;
  }
  const auto newline = text.find('\n');
  m.seconds = std::atof(text.substr(0, newline).c_str());
  m.note = newline == std::string::npos ? "" : text.substr(newline + 1);
  m.ok = m.seconds >= 0;
  return m;
}

// The phases of one piece of work, timed in one child: each phase's seconds and the process's
// peak resident memory when it ended (a phase's own cost is its growth over the phase before).
struct Phase {
  std::string name;
  double seconds = 0;
  double peak_mb = 0;
};

double own_peak_mb() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// Runs `work` in a child process; `work` appends its phases (empty: failed, with `note`).
std::vector<Phase> phases_in_child(const std::function<void(std::vector<Phase>&, std::string&)>& work) {
  std::vector<Phase> phases;
  std::string note;
  const Measure m = in_child([&](std::string& child_note) {
    std::vector<Phase> done;
    work(done, child_note);
    if (done.empty()) return -1.0;
    // The phases travel in the note: "name seconds peak" per line.
    for (const Phase& p : done)
      child_note += p.name + " " + std::to_string(p.seconds) + " " + std::to_string(p.peak_mb) + "\n";
    return 0.0;
  });
  if (!m.ok) {
    phases.push_back(Phase{"failed: " + (m.note.empty() ? std::string("child died") : m.note), -1, m.peak_mb});
    return phases;
  }
  std::size_t at = 0;
  for (std::size_t end; (end = m.note.find('\n', at)) != std::string::npos; at = end + 1) {
    char name[64];
    Phase p;
    if (std::sscanf(m.note.substr(at, end - at).c_str(), "%63s %lf %lf", name, &p.seconds, &p.peak_mb) == 3) {
      p.name = name;
      phases.push_back(p);
    }
  }
  return phases;
}

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Real frames (the Xface emotions of the corpus, blinks and all), repeated and renumbered to
// `frames`, written as a safe .fap in slices so that the generator never holds the whole file.
void write_long_fap(const fs::path& path, std::int64_t frames) {
  std::vector<fapc::FapFrame> real;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(FAPC_SOURCE_DIR "/corpus/fap/bestdpf__xface-new"))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    auto bytes = fapc::read_file_bytes(file.string());
    auto read = fapc::read_fap_text(*bytes, file.string());
    for (const fapc::FapFrame& f : read->sequence.frames) real.push_back(f);
  }
  std::ofstream out(path, std::ios::binary);
  out << "2.1 long 25 " << frames << "\n";
  fapc::FapWriteOptions options;
  options.renumber = false;
  for (std::int64_t first = 0; first < frames; first += 1000) {
    fapc::FapSequence slice{"long", 25, {}};
    for (std::int64_t k = first; k < std::min(frames, first + 1000); ++k) {
      slice.frames.push_back(real[static_cast<std::size_t>(k) % real.size()]);
      slice.frames.back().number = k;
    }
    const std::string text = fapc::write_fap_text(slice, options);
    out << text.substr(text.find('\n') + 1);
  }
}

// Runs convert from `input` to `output` in the child; the seconds of the whole conversion.
double convert_case(const fs::path& input, const fs::path& output, std::string& note) {
  const auto start = std::chrono::steady_clock::now();
  const fp::ConvertResult r = fp::convert(input.string(), {{output.string(), ""}}, fp::ConvertOptions{});
  const double seconds = since(start);
  if (!r.ok()) {
    note = fapc::format_diagnostic(*r.error);
    return -1;
  }
  return seconds;
}

// Loads `input` (not timed), then times writing it as `output` (the writer alone).
double writer_case(const fs::path& input, const fs::path& output, std::string& note) {
  auto loaded = fp::load(input.string(), fp::ConvertOptions{});
  if (!loaded) {
    note = fapc::format_diagnostic(loaded.error());
    return -1;
  }
  const auto start = std::chrono::steady_clock::now();
  auto bytes = fp::render_output(*loaded, {output.string(), ""}, fp::ConvertOptions{});
  const double seconds = since(start);
  if (!bytes) {
    note = fapc::format_diagnostic(bytes.error());
    return -1;
  }
  return seconds;
}

double load_case(const fs::path& input, std::string& note) {
  const auto start = std::chrono::steady_clock::now();
  auto loaded = fp::load(input.string(), fp::ConvertOptions{});
  const double seconds = since(start);
  if (!loaded) {
    note = fapc::format_diagnostic(loaded.error());
    return -1;
  }
  return seconds;
}

double verify_case(const fs::path& input, std::string& note) {
  const auto start = std::chrono::steady_clock::now();
  const fp::VerifyResult r = fp::verify(input.string(), fp::ConvertOptions{});
  const double seconds = since(start);
  if (r.error) {
    note = fapc::format_diagnostic(*r.error);
    return -1;
  }
  return seconds;
}

// The slope of log(seconds) over log(size): the growth exponent.
double growth(const std::vector<std::pair<double, double>>& points) {
  if (points.size() < 2) return NAN;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [n, t] : points) {
    const double x = std::log(n), y = std::log(std::max(t, 1e-6));
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double k = static_cast<double>(points.size());
  return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

struct Bench {
  std::int64_t max_size = 1'000'000;
  std::string only;
  fs::path folder;

  bool wanted(const std::string& name) const { return only.empty() || name.find(only) != std::string::npos; }

  // One case over sizes: prints a line per size and the exponent between 10^4 and the largest.
  void series(const std::string& name, const std::vector<std::int64_t>& sizes,
              const std::function<Measure(std::int64_t)>& run, const char* unit = "frames") {
    if (!wanted(name)) return;
    std::vector<std::pair<double, double>> fitted;
    for (const std::int64_t n : sizes) {
      if (n > max_size) continue;
      const Measure m = run(n);
      if (!m.ok) {
        std::printf("%-28s %9lld %-8s  failed: %s\n", name.c_str(), static_cast<long long>(n), unit, m.note.c_str());
        continue;
      }
      std::printf("%-28s %9lld %-8s %8.3f s %8.1f MB peak %8.3f s cpu\n", name.c_str(), static_cast<long long>(n), unit,
                  m.seconds, m.peak_mb, m.cpu_seconds);
      std::fflush(stdout);
      if (n >= 10'000) fitted.emplace_back(static_cast<double>(n), m.seconds);
    }
    if (fitted.size() >= 2) std::printf("%-28s growth exponent %.2f\n", name.c_str(), growth(fitted));
  }

  // One piece of work in phases over sizes: a line per size and phase, then each phase's exponent.
  void phased_series(const std::string& name, const std::vector<std::int64_t>& sizes,
                     const std::function<std::vector<Phase>(std::int64_t)>& run, const char* unit) {
    if (!wanted(name)) return;
    std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> fitted;  // by phase
    for (const std::int64_t n : sizes) {
      if (n > max_size) continue;
      for (const Phase& p : run(n)) {
        const std::string label = name + " " + p.name;
        if (p.seconds < 0) {
          std::printf("%-28s %9lld %-8s  %s\n", name.c_str(), static_cast<long long>(n), unit, p.name.c_str());
          continue;
        }
        std::printf("%-28s %9lld %-8s %8.3f s %8.1f MB peak at its end\n", label.c_str(), static_cast<long long>(n),
                    unit, p.seconds, p.peak_mb);
        std::fflush(stdout);
        if (n < 10'000) continue;
        auto it = std::find_if(fitted.begin(), fitted.end(), [&](const auto& f) { return f.first == p.name; });
        if (it == fitted.end()) it = fitted.insert(fitted.end(), {p.name, {}});
        it->second.emplace_back(static_cast<double>(n), p.seconds);
      }
    }
    for (const auto& [phase, points] : fitted)
      if (points.size() >= 2) std::printf("%-28s growth exponent %.2f\n", (name + " " + phase).c_str(), growth(points));
  }

  fs::path long_fap(std::int64_t frames) {
    const fs::path path = folder / ("long-" + std::to_string(frames) + ".fap");
    if (!fs::exists(path)) in_child([&](std::string&) { return write_long_fap(path, frames), 0.0; });
    return path;
  }
  fs::path long_fba(std::int64_t frames) {
    const fs::path path = folder / ("long-" + std::to_string(frames) + ".fba");
    const fs::path fap = long_fap(frames);
    if (!fs::exists(path)) in_child([&](std::string& note) { return convert_case(fap, path, note); });
    return path;
  }

  void run() {
    const std::vector<std::int64_t> frames{1'000, 10'000, 100'000, 1'000'000};
    series("fap read (MB/s below)", frames, [&](std::int64_t n) {
      const fs::path input = long_fap(n);
      Measure m = in_child([&](std::string& note) { return load_case(input, note); });
      if (m.ok)
        std::printf("  .fap of %.1f MB read at %.0f MB/s (%.0f MB/s of CPU)\n",
                    static_cast<double>(fs::file_size(input)) / 1e6,
                    static_cast<double>(fs::file_size(input)) / 1e6 / m.seconds,
                    static_cast<double>(fs::file_size(input)) / 1e6 / m.cpu_seconds);
      return m;
    });
    for (const char* ext : {".fba", ".mp4", ".fap"})
      series(std::string(".fap -> ") + ext, frames, [&](std::int64_t n) {
        const fs::path input = long_fap(n);
        return in_child(
            [&](std::string& note) { return convert_case(input, folder / ("out" + std::string(ext)), note); });
      });
    // Decoding as a user does it, to a file: streamed, the frames never all in memory.
    series(".fba decode (-> .fap)", frames, [&](std::int64_t n) {
      const fs::path input = long_fba(n);
      return in_child([&](std::string& note) { return convert_case(input, folder / "decoded.fap", note); });
    });
    // Loading every decoded frame (what `combine`, `plot` and the curves need).
    series(".fba load (all frames)", frames, [&](std::int64_t n) {
      const fs::path input = long_fba(n);
      return in_child([&](std::string& note) { return load_case(input, note); });
    });
    series("verify .fba", frames, [&](std::int64_t n) {
      const fs::path input = long_fba(n);
      return in_child([&](std::string& note) { return verify_case(input, note); });
    });
    for (const char* ext : {".json", ".svg"})
      series(std::string("writer ") + ext + " (frames)", frames, [&](std::int64_t n) {
        const fs::path input = long_fap(n);
        return in_child(
            [&](std::string& note) { return writer_case(input, folder / ("out" + std::string(ext)), note); });
      });
#ifdef FAPC_SCALE_SCRIPTS
    run_scripts();
#else
    std::printf("(script front ends: bench/script_generators.hpp is not in this tree)\n");
#endif
  }

#ifdef FAPC_SCALE_SCRIPTS
  // Each front end's script of n elements (issue 19a's generators) compiled to .fba at 10 fps,
  // where 10^6 elements fit the default frame limit: the whole compile, parse to encode.
  void run_scripts() {
    for (const fapc::bench::ScriptKind kind : fapc::bench::kScriptKinds) {
      const std::string kind_name = fapc::bench::name(kind);
      const std::vector<std::int64_t> sizes{1'000, 10'000, 100'000, 1'000'000};
      const auto script_of = [&](std::int64_t n) {
        const fs::path script = folder / (kind_name + "-" + std::to_string(n) + fapc::bench::extension(kind));
        if (!fs::exists(script))
          in_child([&](std::string&) {
            std::ofstream(script, std::ios::binary) << fapc::bench::generate_script(kind, static_cast<std::size_t>(n));
            return 0.0;
          });
        return script;
      };
      // The library's stages one after the other: the front end to its timeline (parse, expand,
      // schedule, lower), every frame rendered and held, the frames encoded.
      phased_series(
          kind_name + " phase", sizes,
          [&](std::int64_t n) {
            const fs::path script = script_of(n);
            return phases_in_child([&](std::vector<Phase>& phases, std::string& note) {
              fp::ConvertOptions options;
              options.fps = 10;
              options.render = false;
              options.curves = false;
              auto start = std::chrono::steady_clock::now();
              auto lowered = fp::load(script.string(), options);
              if (!lowered) return void(note = fapc::format_diagnostic(lowered.error()));
              phases.push_back({"lower", since(start), own_peak_mb()});
              start = std::chrono::steady_clock::now();
              fapc::RenderOptions render;
              render.fps = 10;
              auto rendered = fapc::render_frames(*lowered->timeline, render);
              if (!rendered) return phases.clear(), void(note = fapc::format_diagnostic(rendered.error()));
              phases.push_back({"render", since(start), own_peak_mb()});
              start = std::chrono::steady_clock::now();
              auto encoded = fapc::encode_fba(rendered->frames, fapc::FbaEncodeOptions{});
              if (!encoded) return phases.clear(), void(note = fapc::format_diagnostic(encoded.error()));
              phases.push_back({"encode", since(start), own_peak_mb()});
            });
          },
          "elements");
      // The whole compile as `fapc compile x -o x.fba` runs it (frames streamed to the encoder).
      series(
          kind_name + " -> .fba (10 fps)", sizes,
          [&](std::int64_t n) {
            const fs::path script = script_of(n);
            return in_child([&](std::string& note) {
              fp::ConvertOptions options;
              options.fps = 10;
              const auto start = std::chrono::steady_clock::now();
              const fp::ConvertResult r =
                  fp::convert(script.string(), {{(folder / "script.fba").string(), ""}}, options);
              if (!r.ok()) return note = fapc::format_diagnostic(*r.error), -1.0;
              return since(start);
            });
          },
          "elements");
      // The curves step of a script's compile (25 fps), and the curves JSON written from them:
      // the timeline compiled untimed, without frames.
      for (const bool json : {false, true})
        series(
            kind_name + (json ? " curves -> .json" : " curves (25 fps)"), sizes,
            [&](std::int64_t n) {
              const fs::path script = script_of(n);  // named by kind: xmto and xmto-to share an extension
              return in_child([&](std::string& note) { return curves_case(script, json, note); });
            },
            "elements");
    }
  }

  // Times render_curves (or, with `json`, the curves JSON writer given the curves) on `script`.
  static double curves_case(const fs::path& script, bool json, std::string& note) {
    fp::ConvertOptions options;
    options.render = false;
    auto loaded = fp::load(script.string(), options);
    if (!loaded) return note = fapc::format_diagnostic(loaded.error()), -1.0;
    if (!loaded->timeline) return note = "no timeline", -1.0;
    auto start = std::chrono::steady_clock::now();
    loaded->curves = fapc::render_curves(*loaded->timeline, fapc::CurveOptions{25, 1e-6});
    if (!json) return since(start);
    start = std::chrono::steady_clock::now();
    auto bytes = fp::render_output(*loaded, {(script.string() + ".json"), ""}, fp::ConvertOptions{});
    if (!bytes) return note = fapc::format_diagnostic(bytes.error()), -1.0;
    return since(start);
  }
#endif
};

}  // namespace

int main(int argc, char** argv) {
  // The allocator as fapc's main() sets it (its children inherit it), so that the figures are
  // those of the program.
  mallopt(M_MMAP_THRESHOLD, 256 * 1024);
  Bench bench;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--max") && i + 1 < argc)
      bench.max_size = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--only") && i + 1 < argc)
      bench.only = argv[++i];
    else if (!std::strcmp(argv[i], "--folder") && i + 1 < argc)
      bench.folder = argv[++i];
    else {
      std::fprintf(stderr, "usage: scale_bench [--max N] [--only SUBSTRING] [--folder DIR]\n");
      return 2;
    }
  }
  const bool kept = !bench.folder.empty();
  char folder[] = "/tmp/fapc-scale-XXXXXX";
  if (kept)
    fs::create_directories(bench.folder);
  else if (::mkdtemp(folder))
    bench.folder = folder;
  else
    return 1;
  std::printf(
      "scale bench: one core, each case in its own process; times of the case's work, peak RSS of its process\n");
  bench.run();
  if (!kept) fs::remove_all(bench.folder);
  return 0;
}

// fapc: one program, subcommands registered by their own files (commands.hpp), declared with their
// options in cli_spec.cpp. main() handles what every subcommand shares: --help, -q/-v, the
// version, "did you mean" for a misspelt subcommand, and the warning counts at the end.
#include <malloc.h>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "fapc/args.hpp"
#include "fapc/cli_spec.hpp"
#include "fapc/codec/did_you_mean.hpp"
#include "fapc/commands.hpp"
#include "fapc/help.hpp"
#include "fapc/report.hpp"
#include "fapc/speech/engine.hpp"

namespace {

using namespace fapc::cli;

int unknown_command(const std::string& name, const std::vector<std::string>& args) {
  std::vector<std::string> names;
  for (const CommandSpec& c : command_specs()) names.emplace_back(c.name);
  std::string hint = fapc::did_you_mean(name, names);
  // `fapc x.mimic -o x.mp4`: a file where the subcommand goes.
  if (hint.empty() && std::filesystem::is_regular_file(name)) {
    hint = "; did you mean fapc compile " + name;
    for (std::size_t i = 1; i < args.size(); ++i) hint += " " + args[i];
    hint += "?";
  }
  std::cerr << "fapc: ";
  if (verbosity() == Verbosity::verbose) std::cerr << "error[" << fapc::codes::cli::unknown_command.name << "]: ";
  std::cerr << "unknown command '" << name << "'" << hint << " (try fapc --help)\n";
  return kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  // A closed pipe is an error the writer reports (streams.hpp), not a silent death that would
  // skip the removal of temporary files.
  std::signal(SIGPIPE, SIG_IGN);
  // Blocks of 256 KiB and more come from the system and go back to it when freed. glibc would
  // raise this threshold after the first large free (up to 32 MiB), and then the big vectors a
  // long script's compile frees stay in the heap, pinned by small blocks allocated after them:
  // 50 to 90 MB of the peak of a 10^6-element compile (docs/building.md, "Memory").
  mallopt(M_MMAP_THRESHOLD, 256 * 1024);
  std::vector<std::string> args(argv + 1, argv + argc);
  // -q and -v may come before the subcommand too.
  while (!args.empty() &&
         (args.front() == "-q" || args.front() == "--quiet" || args.front() == "-v" || args.front() == "--verbose")) {
    set_verbosity(args.front() == "-q" || args.front() == "--quiet" ? Verbosity::quiet : Verbosity::verbose);
    args.erase(args.begin());
  }
  if (args.empty()) {
    print_overview(std::cerr);
    return kExitUsage;
  }
  const std::string name = args.front();
  if (name == "--help" || name == "-h") return commands().at("help").run({});
  if (name == "--version" || name == "-V") {
    std::cout << version_text() << '\n';
    return kExitOk;
  }
  const auto& table = commands();
  const auto it = table.find(name);
  if (it == table.end() || !find_command_spec(name)) return unknown_command(name, args);
  args.erase(args.begin());
  // What every subcommand shares; the subcommand parses again for its own options (and reports
  // their errors), so a parse error here only stops the search.
  const Args common(name, args);
  if (common.flag("help")) {
    print_command_help(*find_command_spec(name), std::cout);
    return kExitOk;
  }
  if (common.flag("quiet")) set_verbosity(Verbosity::quiet);
  if (common.flag("verbose")) set_verbosity(Verbosity::verbose);
  // A command that may speak (one that takes --speech-rate) starts the speech engine's process
  // now, while fapc has a single thread: readers run on a thread of their own (deep_stack.hpp) and
  // a batch on several, and speech must not fork from there (fapc/speech/engine.hpp).
  if (const OptionSpec* rate = find_option("speech-rate"); rate != nullptr && rate->applies_to(name))
    fapc::speech::start_engine_process();
  const int status = it->second.run(args);
  finish_reports();
  return status;
}

// fapc info FILE [--json]: what a file holds.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "fapc/args.hpp"
#include "fapc/registry.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

struct Range {
  long long min = 0, max = 0, frames = 0;
};

nlohmann::ordered_json summarise(const std::string& path, const std::string& kind,
                                 const Loaded& loaded) {
  const FapSequence& seq = loaded.frames;
  std::map<int, Range> ranges;
  for (const FapFrame& frame : seq.frames)
    for (int fap = 1; fap <= kFapCount; ++fap) {
      if (!frame.has(fap)) continue;
      const long long v = fap == 1   ? frame.viseme.select1
                          : fap == 2 ? frame.expression.select1
                                     : frame.value(fap);
      Range& r = ranges[fap];
      r.min = r.frames ? std::min(r.min, v) : v;
      r.max = r.frames ? std::max(r.max, v) : v;
      ++r.frames;
    }
  nlohmann::ordered_json out;
  out["file"] = path;
  out["kind"] = kind;
  out["name"] = seq.name;
  out["fps"] = seq.fps;
  out["frames"] = seq.frames.size();
  out["duration"] = seq.duration_seconds();
  nlohmann::ordered_json faps = nlohmann::ordered_json::array();
  for (const auto& [fap, r] : ranges) {
    const FapInfo& info = *find_fap(fap);
    faps.push_back({{"number", fap}, {"name", info.name}, {"unit", fapu_name(info.unit)},
                    {"min", r.min}, {"max", r.max}, {"frames", r.frames}});
  }
  out["faps used"] = faps.size();
  out["faps"] = faps;
  return out;
}

std::string scalar_text(const nlohmann::ordered_json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_array()) {
    std::string out;
    for (const auto& item : v) out += (out.empty() ? "" : ", ") + scalar_text(item);
    return out.empty() ? "none" : out;
  }
  if (v.is_number_float()) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(3) << v.get<double>();
    return s.str();
  }
  return v.dump();
}

void print_text(const nlohmann::ordered_json& info) {
  for (const auto& [key, value] : info.items()) {
    if (key == "faps" || key == "warnings") continue;
    if (value.is_object()) {
      std::cout << key << ":\n";
      for (const auto& [k, v] : value.items()) std::cout << "  " << k << ": " << scalar_text(v) << '\n';
    } else {
      std::cout << key << ": " << scalar_text(value) << '\n';
    }
  }
  for (const auto& f : info["faps"]) {
    std::cout << "  " << std::left << std::setw(4) << f["number"].get<int>() << std::setw(24)
              << f["name"].get<std::string>() << std::setw(6) << f["unit"].get<std::string>()
              << f["min"].get<long long>() << " .. " << f["max"].get<long long>() << " in "
              << f["frames"].get<long long>() << " frames\n";
  }
  std::cout << "warnings: " << info["warnings"].size() << '\n';
  for (const auto& w : info["warnings"]) std::cout << "  " << w.get<std::string>() << '\n';
}

int run_info(const std::vector<std::string>& argv) {
  Args args(argv, {}, {"json"});
  if (!args.ok()) return usage_error("info", args.error());
  if (args.positionals().size() != 1) return usage_error("info", "expected one FILE");
  const std::string& path = args.positionals().front();
  const InputFormat* format = input_format_for(path);
  if (!format) {
    report(make_error(Location{path, 0, 0, -1}, "unknown input kind"));
    return kExitBadInput;
  }
  const ReadingInput reading(path, ConvertOptions{});  // for its includes, as load_input would
  const ConvertOptions& options = reading.options();
  auto loaded = format->load(path, options);
  if (!loaded) {
    report(loaded.error());
    return kExitBadInput;
  }
  nlohmann::ordered_json info = summarise(path, format->kind, *loaded);
  if (format->describe) {
    auto facts = format->describe(path, options);
    if (!facts) {
      report(facts.error());
      return kExitBadInput;
    }
    info["format"] = *facts;
  }
  info["warnings"] = nlohmann::ordered_json::array();
  for (const Diagnostic& w : loaded->warnings) info["warnings"].push_back(format_diagnostic(w));
  if (args.flag("json")) {
    std::cout << info.dump(2) << '\n';
  } else {
    print_text(info);
  }
  return kExitOk;
}

const RegisterCommand info_command{"info", "fapc info FILE [--json]", run_info};

}  // namespace

}  // namespace fapc::cli

// .json output: the curves JSON of docs/cli.md (time-value lists after blending and thinning).
#include <cstdio>

#include "formats.hpp"

namespace fapc::pipeline::builtin {

namespace {

// Ten significant digits: far below any tolerance of the data, and golden files do not change
// with the last bits of a sine between compilers.
std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

Result<std::string> write_curves_json(const Loaded& loaded, const std::string&,
                                      const ConvertOptions&) {
  const Curves curves = loaded.curves ? *loaded.curves : curves_from_frames(loaded.frames);
  // One target per line, its points inline: diffs of golden files stay readable.
  using json = nlohmann::json;
  std::string out = "{\n \"fps\": " + json(curves.fps).dump() +
                    ",\n \"duration\": " + number(curves.duration) + ",\n \"curves\": {";
  const char* separator = "\n";
  for (const auto& [target, points] : curves.curves) {
    out += separator;
    out += "  " + json(target).dump() + ": [";
    for (std::size_t i = 0; i < points.size(); ++i) {
      out += (i ? ", [" : "[") + number(points[i].first) + ", " + number(points[i].second) + "]";
    }
    out += "]";
    separator = ",\n";
  }
  return out + "\n }\n}\n";
}

}  // namespace

OutputFormat curves_json_output() { return {"json", {".json"}, write_curves_json, true}; }

}  // namespace fapc::pipeline::builtin

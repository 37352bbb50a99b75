// .json output: the curves JSON of docs/cli.md (time-value lists after blending and thinning).
#include <charconv>

#include "formats.hpp"

namespace fapc::pipeline::builtin {

namespace {

// Ten significant digits: far below any tolerance of the data, and golden files do not change
// with the last bits of a sine between compilers. std::to_chars with a precision prints what
// printf's "%.10g" prints (the standard defines it so), without printf's cost per number, which
// made the curves JSON of a long animation five times slower than encoding it.
void append_number(std::string& out, double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v, std::chars_format::general, 10).ptr;
  out.append(text, end);
}

Result<std::string> write_curves_json(const Loaded& loaded, const std::string&,
                                      const ConvertOptions&) {
  // The script's curves when there are some (not copied), else curves made from the frames.
  std::optional<Curves> from_frames;
  if (!loaded.curves) from_frames = curves_from_frames(loaded.frames);
  const Curves& curves = loaded.curves ? *loaded.curves : *from_frames;
  // One target per line, its points inline: diffs of golden files stay readable.
  using json = nlohmann::json;
  std::string out = "{\n \"fps\": " + json(curves.fps).dump() + ",\n \"duration\": ";
  append_number(out, curves.duration);
  out += ",\n \"curves\": {";
  const char* separator = "\n";
  for (const auto& [target, points] : curves.curves) {
    out += separator;
    out += "  " + json(target).dump() + ": [";
    for (std::size_t i = 0; i < points.size(); ++i) {
      out += i ? ", [" : "[";
      append_number(out, points[i].first);
      out += ", ";
      append_number(out, points[i].second);
      out += ']';
    }
    out += "]";
    separator = ",\n";
  }
  return out + "\n }\n}\n";
}

}  // namespace

OutputFormat curves_json_output() { return {"json", {".json"}, write_curves_json, true}; }

}  // namespace fapc::pipeline::builtin

// .fap and .fap.gz, in and out.
#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"
#include "formats.hpp"

namespace fapc::pipeline::builtin {

namespace {

nlohmann::ordered_json facts_of(const FapFileFacts& facts) {
  nlohmann::ordered_json out;
  out["variant"] = facts.variant();
  if (facts.has_header) {
    out["version"] = facts.version;
    out["header_name"] = facts.header_name;
    out["header_frame_count"] = facts.header_count;
  }
  out["deviations"] = facts.deviations();
  return out;
}

Result<Loaded> load_fap(const std::string& path, const ConvertOptions& options) {
  auto bytes = read_file_bytes(path, options.limits);
  if (!bytes) return bytes.error();
  FapReadOptions read_options;
  read_options.max_frames = options.limits.max_frames;
  auto read = read_fap_text(*bytes, path, read_options);
  if (!read) return read.error();
  Loaded loaded;
  loaded.frames = std::move(read->sequence);
  if (read->facts.has_header) {
    loaded.rate_at = read->facts.header_fps_at;
    loaded.rate_written = loaded.frames.fps;
  }
  loaded.frame_lines = std::move(read->value_lines);
  loaded.warnings = std::move(read->warnings);
  if (options.facts) loaded.facts = facts_of(read->facts);
  return loaded;
}

Result<std::string> write_fap(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  FapWriteOptions write;
  write.flavour = options.fap_flavour;
  auto text = write_fap_flavour(loaded.frames, write);
  if (!text) return Diagnostic{text.error().severity, Location{path, 0, 0, -1}, text.error().message, {}, text.error().kind};
  return text;
}

}  // namespace

InputFormat fap_input() { return {"fap", {".fap", ".fap.gz", ".FAP"}, load_fap}; }
OutputFormat fap_output() { return {"fap", {".fap", ".fap.gz"}, write_fap}; }

}  // namespace fapc::pipeline::builtin

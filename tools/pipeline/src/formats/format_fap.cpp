// .fap and .fap.gz, in and out.
#include <optional>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"
#include "fap_text_outputs.hpp"
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
  // Mapped, not copied: the text is read once, and its pages are let go behind the reader (the
  // frames are what is kept). A gzip file is inflated whole; an empty one (or one of /proc, which
  // says it is empty) is read the usual way.
  auto mapped = MappedFile::open(path);
  if (!mapped) return mapped.error();
  std::optional<std::string> bytes;
  if (mapped->bytes().empty() || is_gzip(mapped->bytes())) {
    auto read = read_file_bytes(path, options.limits);
    if (!read) return read.error();
    bytes = std::move(*read);
  }
  const std::string_view text = bytes ? std::string_view(*bytes) : mapped->bytes();
  FapReadOptions read_options;
  read_options.max_frames = options.limits.max_frames;
  const auto let_go = [&](std::size_t offset) {
    if (!bytes) mapped->release(offset);
  };
  auto read = read_fap_text(text, path, read_options, let_go);
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
  auto text = write_fap_flavour(loaded.frames, fap_write_options(options));
  if (!text) return fap_writer_error_at(text.error(), path);
  return text;
}

}  // namespace

InputFormat fap_input() { return {"fap", {".fap", ".fap.gz", ".FAP"}, load_fap}; }
OutputFormat fap_output() { return {"fap", {".fap", ".fap.gz"}, write_fap}; }

}  // namespace fapc::pipeline::builtin

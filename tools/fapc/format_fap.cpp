// .fap and .fap.gz, in and out.
#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/registry.hpp"

namespace fapc::cli {

namespace {

Result<FapReadResult> read_fap_path(const std::string& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return read_fap_text(*bytes, path);
}

Result<Loaded> load_fap(const std::string& path, const ConvertOptions&) {
  auto read = read_fap_path(path);
  if (!read) return read.error();
  Loaded loaded;
  loaded.frames = std::move(read->sequence);
  loaded.warnings = std::move(read->warnings);
  return loaded;
}

Result<nlohmann::ordered_json> describe_fap(const std::string& path, const ConvertOptions&) {
  auto read = read_fap_path(path);
  if (!read) return read.error();
  const FapFileFacts& facts = read->facts;
  nlohmann::ordered_json out;
  out["variant"] = facts.variant();
  if (facts.has_header) {
    out["version"] = facts.version;
    out["header name"] = facts.header_name;
    out["header frame count"] = facts.header_count;
  }
  out["deviations"] = facts.deviations();
  return out;
}

Result<std::string> write_fap(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  FapWriteOptions write;
  write.flavour = options.fap_flavour;
  auto text = write_fap_flavour(loaded.frames, write);
  if (!text) return Diagnostic{text.error().severity, Location{path, 0, 0, -1}, text.error().message, {}, text.error().kind};
  return text;
}

const RegisterInput fap_input{InputFormat{"fap", {".fap", ".fap.gz", ".FAP"}, load_fap, describe_fap}};
const RegisterOutput fap_output{OutputFormat{"fap", {".fap", ".fap.gz"}, write_fap}};

}  // namespace

}  // namespace fapc::cli

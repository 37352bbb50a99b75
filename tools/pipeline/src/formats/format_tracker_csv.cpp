// .csv inputs: OpenFace's and ARKit's CSVs, told apart by their header (bridges/csv_kind.hpp).
#include <filesystem>

#include "bridges.hpp"
#include "bridges/arkit_csv.hpp"
#include "bridges/csv_kind.hpp"
#include "bridges/openface_csv.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/json_access.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<Loaded> load_as(const std::string& path, const ConvertOptions& options, std::optional<bridges::CsvKind> kind) {
  Result<std::string> bytes = read_file_bytes(path, options.limits);
  if (!bytes) return bytes.error();
  if (!kind) {
    Result<bridges::CsvKind> found = bridges::csv_kind(*bytes, path);
    if (!found) return found.error();
    kind = *found;
  }
  const bridges::TrackOptions track{options.fps, options.limits};
  Result<bridges::TrackRead> read = *kind == bridges::CsvKind::openface
                                        ? bridges::read_openface_csv(*bytes, path, track)
                                        : bridges::read_arkit_csv(*bytes, path, track);
  if (!read) return read.error();
  Loaded loaded;
  loaded.frames = std::move(read->frames);
  loaded.frames.name = std::filesystem::path(path).stem().string();
  loaded.warnings = std::move(read->warnings);
  if (options.facts) json_of(loaded.facts)["dialect"] = *kind == bridges::CsvKind::openface ? "OpenFace" : "ARKit";
  return loaded;
}

}  // namespace

InputFormat tracker_csv_input() {
  return {"csv", {".csv"}, [](const std::string& path, const ConvertOptions& options) {
            return load_as(path, options, std::nullopt);
          }};
}
InputFormat openface_csv_input() {
  return {"openface", {".au.csv"}, [](const std::string& path, const ConvertOptions& options) {
            return load_as(path, options, bridges::CsvKind::openface);
          }};
}
InputFormat arkit_csv_input() {
  return {"arkit", {".arkit.csv"}, [](const std::string& path, const ConvertOptions& options) {
            return load_as(path, options, bridges::CsvKind::arkit);
          }};
}

}  // namespace fapc::pipeline::builtin

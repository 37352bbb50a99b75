// The bridge outputs: ARKit CSV (.arkit.csv), OpenFace action units (.au.csv) and the viseme
// track (.visemes.json, .visemes.csv); each says what it loses (bridges/losses.cpp).
#include "bridges.hpp"
#include "bridges/writers.hpp"

namespace fapc::pipeline::builtin {

namespace {

OutputFormat bridge_output(std::string kind, std::string extension, std::string (*write)(const FapSequence&),
                           bridges::Carrier carrier) {
  OutputFormat format{std::move(kind),
                      {std::move(extension)},
                      [write](const Loaded& loaded, const std::string&, const ConvertOptions&) -> Result<std::string> {
                        return write(loaded.frames);
                      }};
  format.losses = [carrier](const Loaded& loaded, const std::string& path) {
    return bridges::losses(loaded.frames, carrier, path);
  };
  return format;
}

}  // namespace

OutputFormat arkit_csv_output() {
  return bridge_output("arkit-csv", ".arkit.csv", bridges::write_arkit_csv, bridges::Carrier::arkit);
}
OutputFormat openface_csv_output() {
  return bridge_output("au-csv", ".au.csv", bridges::write_openface_csv, bridges::Carrier::openface);
}
OutputFormat viseme_json_output() {
  return bridge_output("visemes", ".visemes.json", bridges::write_viseme_json, bridges::Carrier::visemes);
}
OutputFormat viseme_csv_output() {
  return bridge_output("vis-csv", ".visemes.csv", bridges::write_viseme_csv, bridges::Carrier::visemes);
}

}  // namespace fapc::pipeline::builtin

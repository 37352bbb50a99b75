// The bridges' round trips, measured (docs/bridges.md, "Measured"):
//   FAP -> ARKit -> FAP and FAP -> AU -> FAP over every animation of corpus/examples and
//   corpus/fap, the error per FAP group; ARKit -> FAP -> ARKit over the real takes of
//   corpus/arkit, the error per shape group.
// Run from the top of the repository: build/bin/bridges_bench. Prints Markdown tables.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fapc/face/face_track.hpp"
#include "fapc/pipeline/registry.hpp"
#include "fapc/vocabulary/arkit_shapes.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "fapc/vocabulary/shape_basis.hpp"

namespace {

using fapc::vocabulary::FapVector;
using fapc::vocabulary::ShapeBasis;

// FAPs each CSV carries as angles, not through its shapes: the round trip keeps them exactly.
bool carried_as_angle(int fap) { return (fap >= 23 && fap <= 26) || (fap >= 48 && fap <= 50); }

struct GroupError {
  double abs_error = 0;     // sum of |after - before| over FAPs that move, in FAP units
  double abs_movement = 0;  // sum of |before|
  double worst = 0;
  double samples = 0;
};

std::vector<std::string> corpus_animations() {
  std::vector<std::string> files;
  for (const char* folder : {"corpus/examples", "corpus/fap"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
      if (!entry.is_regular_file()) continue;
      const std::string path = entry.path().string();
      if (fapc::pipeline::formats().input_for(path)) files.push_back(path);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

ShapeBasis arkit_basis() {
  std::vector<std::string> keys;
  for (std::string_view name : fapc::vocabulary::arkit_shape_names()) keys.emplace_back(name);
  return ShapeBasis(fapc::vocabulary::arkit_table(), keys);
}

ShapeBasis openface_basis() {
  std::vector<std::string> keys;
  for (int au : {1, 2, 4, 5, 6, 7, 9, 10, 12, 14, 15, 17, 20, 23, 25, 26, 45}) keys.push_back(std::to_string(au));
  return ShapeBasis(fapc::vocabulary::action_unit_table(), keys);
}

void fap_round_trips() {
  const ShapeBasis bases[2] = {arkit_basis(), openface_basis()};
  std::map<int, GroupError> errors[2];
  int files = 0;
  long frames = 0;
  fapc::pipeline::ConvertOptions options;
  options.speech_engine = true;
  for (const std::string& path : corpus_animations()) {
    auto loaded = fapc::pipeline::load(path, options);
    if (!loaded || loaded->frames.frames.empty()) continue;
    ++files;
    const fapc::face::FaceTrack track(loaded->frames);
    std::vector<double> weights[2];
    for (std::int64_t k = 0; k < track.frame_count(); ++k) {
      ++frames;
      const FapVector& before = track.at_frame(k);
      for (int b = 0; b < 2; ++b) {
        weights[b] = bases[b].from_faps(before);
        const FapVector after = bases[b].to_faps(weights[b]);
        for (int fap = 3; fap <= fapc::kFapCount; ++fap) {
          const auto i = static_cast<std::size_t>(fap - 1);
          if (before[i] == 0) continue;
          const double out = carried_as_angle(fap) ? before[i] : after[i];
          GroupError& g = errors[b][fapc::fap_table()[i].group];
          g.abs_error += std::abs(out - before[i]);
          g.abs_movement += std::abs(before[i]);
          g.worst = std::max(g.worst, std::abs(out - before[i]));
          ++g.samples;
        }
      }
    }
  }
  std::printf(
      "FAP -> ARKit -> FAP and FAP -> AU -> FAP: %d animations of corpus/examples and corpus/fap, "
      "%ld frames\n\n",
      files, frames);
  std::printf(
      "| FAP group | values | ARKit: mean error | ARKit: error / movement | ARKit: worst | "
      "AU: mean error | AU: error / movement | AU: worst |\n|---|---|---|---|---|---|---|---|\n");
  for (const fapc::FapGroup& group : fapc::fap_groups()) {
    if (group.number == 1) continue;
    const GroupError& a = errors[0][group.number];
    const GroupError& u = errors[1][group.number];
    if (a.samples == 0) continue;
    std::printf("| %d %s | %.0f | %.1f | %.0f%% | %.0f | %.1f | %.0f%% | %.0f |\n", group.number,
                std::string(group.name).c_str(), a.samples, a.abs_error / a.samples, 100 * a.abs_error / a.abs_movement,
                a.worst, u.abs_error / u.samples, 100 * u.abs_error / u.abs_movement, u.worst);
  }
}

// A Live Link Face take's shape weights, one vector (LLF order) per row, by a plain split.
std::vector<std::vector<double>> take_weights(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<int> shape_of_column;
  {
    std::istringstream header(line);
    std::string name;
    while (std::getline(header, name, ',')) {
      const auto shape = fapc::vocabulary::find_arkit_shape(name);
      shape_of_column.push_back(shape ? *shape : -1);
    }
  }
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    std::vector<double> w(fapc::vocabulary::kArkitShapeCount, 0.0);
    for (int shape : shape_of_column) {
      if (!std::getline(row, cell, ',')) break;
      if (shape >= 0) w[static_cast<std::size_t>(shape)] = std::stod(cell);
    }
    rows.push_back(std::move(w));
  }
  return rows;
}

void arkit_round_trip() {
  const ShapeBasis basis = arkit_basis();
  const auto& names = fapc::vocabulary::arkit_shape_names();
  // Shapes grouped by their name's first word (eye, jaw, mouth, brow, cheek, nose, tongue).
  std::map<std::string, GroupError> groups;
  std::vector<GroupError> per_shape(names.size());
  long rows_total = 0;
  int takes = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator("corpus/arkit")) {
    if (!entry.is_regular_file() || entry.path().extension() != ".csv") continue;
    ++takes;
    std::vector<double> fitted;
    for (const std::vector<double>& w : take_weights(entry.path().string())) {
      ++rows_total;
      FapVector faps = basis.to_faps(w);
      for (double& v : faps) v = std::round(v);  // a .fap carries whole FAP units
      fitted = basis.from_faps(faps);
      for (std::size_t s = 0; s < w.size(); ++s) {
        std::string name(names[s]);
        std::string group;
        for (char c : name) {
          if (std::isupper(static_cast<unsigned char>(c))) break;
          group += c;
        }
        GroupError& one = per_shape[s];
        one.abs_error += std::abs(fitted[s] - w[s]);
        one.abs_movement += std::abs(w[s]);
        one.samples += 1;
        GroupError& g = groups[group];
        g.abs_error += std::abs(fitted[s] - w[s]);
        g.abs_movement += std::abs(w[s]);
        g.worst = std::max(g.worst, std::abs(fitted[s] - w[s]));
        ++g.samples;
      }
    }
  }
  std::printf("\nARKit -> FAP -> ARKit: %d takes of corpus/arkit, %ld rows; weights 0..1\n\n", takes, rows_total);
  std::printf("| shapes | weights | mean error | error / weight | worst |\n|---|---|---|---|---|\n");
  for (const auto& [group, g] : groups) {
    std::printf("| %s* | %.0f | %.3f | %.0f%% | %.2f |\n", group.c_str(), g.samples, g.abs_error / g.samples,
                g.abs_movement > 0 ? 100 * g.abs_error / g.abs_movement : 0.0, g.worst);
  }
  std::vector<std::size_t> order(names.size());
  for (std::size_t s = 0; s < order.size(); ++s) order[s] = s;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return per_shape[a].abs_error > per_shape[b].abs_error; });
  std::printf("\nThe shapes with the largest mean error (mean weight beside it):");
  for (std::size_t i = 0; i < 8; ++i) {
    const GroupError& g = per_shape[order[i]];
    std::printf("%s %s %.3f (%.3f)", i ? "," : "", std::string(names[order[i]]).c_str(), g.abs_error / g.samples,
                g.abs_movement / g.samples);
  }
  std::printf("\n");
}

}  // namespace

int main() {
  fap_round_trips();
  arkit_round_trip();
  return 0;
}

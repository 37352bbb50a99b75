#include "csv_kind.hpp"

#include "arkit_csv.hpp"
#include "csv_lines.hpp"
#include "fapc/pipeline/codes.hpp"
#include "openface_csv.hpp"

namespace fapc::pipeline::bridges {

Result<CsvKind> csv_kind(std::string_view text, const std::string& file) {
  CsvLines lines(text, file);
  Result<std::vector<std::string>> header = read_header(lines);
  if (!header) return header.error();
  // ARKit first: a Live Link Face take names no OpenFace column, and an OpenFace file no shape.
  if (looks_like_arkit(*header)) return CsvKind::arkit;
  if (looks_like_openface(*header)) return CsvKind::openface;
  if (header->size() >= 2 && (*header)[0] == "frame" && (*header)[1] == "time_s") {
    return make_error(codes::csv::frames_csv, Location::text(file, 1, 1),
                      "a frames CSV as fapc writes it (frame, time_s, FAP columns): fapc does not read it back; "
                      "convert from the .fap file it was made from",
                      std::string(lines.whole()));
  }
  return make_error(codes::csv::unknown_columns, Location::text(file, 1, 1),
                    "not a CSV fapc reads: expected OpenFace's columns (timestamp, AU01_r, pose_Rx, gaze_angle_x...) "
                    "or ARKit's (Timecode, eyeBlinkLeft or EyeBlinkLeft...)",
                    std::string(lines.whole()));
}

}  // namespace fapc::pipeline::bridges

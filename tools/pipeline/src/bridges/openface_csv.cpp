#include "openface_csv.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "csv_lines.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "resampler.hpp"

namespace fapc::pipeline::bridges {
namespace {

// "AU12_r" -> 12; nullopt for other names.
std::optional<int> intensity_column_au(std::string_view name) {
  if (name.size() < 5 || !name.starts_with("AU") || !name.ends_with("_r")) return std::nullopt;
  int au = 0;
  for (char c : name.substr(2, name.size() - 4)) {
    if (c < '0' || c > '9') return std::nullopt;
    au = au * 10 + (c - '0');
    if (au > 99) return std::nullopt;
  }
  return au;
}

bool starts_with_any(std::string_view name, std::initializer_list<std::string_view> prefixes) {
  for (std::string_view p : prefixes)
    if (name.starts_with(p)) return true;
  return false;
}

// Where each value a row carries goes.
struct Columns {
  std::size_t timestamp = 0;
  std::optional<std::size_t> success, confidence, face_id;
  std::optional<std::size_t> gaze_angle_x, gaze_angle_y;
  std::optional<std::size_t> gaze[2][3];  // gaze_0_x .. gaze_1_z: unit vectors per eye
  bool gaze_vectors = false;              // the eyes from gaze_0_* and gaze_1_* (1.x files)
  std::optional<std::size_t> pose[3];     // pose_Rx, pose_Ry, pose_Rz
  struct Unit {
    std::size_t column;
    std::vector<vocabulary::MappingRow> rows;
  };
  std::vector<Unit> units;
  std::bitset<kFapCount> faps;
  std::vector<std::string> unread;
};

void drive(std::bitset<kFapCount>& faps, std::initializer_list<int> numbers) {
  for (int fap : numbers) faps.set(static_cast<std::size_t>(fap - 1));
}

Result<Columns> find_columns(const std::vector<std::string>& header, const std::string& file) {
  Columns c;
  const std::optional<std::size_t> timestamp = column_of(header, "timestamp");
  if (!timestamp) {
    return make_error(codes::openface::no_timestamp, Location::text(file, 1, 1),
                      "an OpenFace CSV without a 'timestamp' column: fapc places rows by it");
  }
  c.timestamp = *timestamp;
  c.success = column_of(header, "success");
  c.confidence = column_of(header, "confidence");
  c.face_id = column_of(header, "face_id");
  c.gaze_angle_x = column_of(header, "gaze_angle_x");
  c.gaze_angle_y = column_of(header, "gaze_angle_y");
  const bool angles = c.gaze_angle_x && c.gaze_angle_y;
  for (int eye = 0; eye < 2; ++eye)
    for (int axis = 0; axis < 3; ++axis)
      c.gaze[eye][axis] = column_of(header, "gaze_" + std::to_string(eye) + "_" + std::string(1, "xyz"[axis]));
  const bool vectors =
      !angles && c.gaze[0][0] && c.gaze[0][1] && c.gaze[0][2] && c.gaze[1][0] && c.gaze[1][1] && c.gaze[1][2];
  c.gaze_vectors = vectors;
  if (angles || vectors) drive(c.faps, {23, 24, 25, 26});
  for (int axis = 0; axis < 3; ++axis) c.pose[axis] = column_of(header, std::string("pose_R") + "xyz"[axis]);
  if (c.pose[0]) drive(c.faps, {48});
  if (c.pose[1]) drive(c.faps, {49});
  if (c.pose[2]) drive(c.faps, {50});
  const vocabulary::MappingTable& table = vocabulary::action_unit_table();
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string& name = header[i];
    const std::optional<int> au = intensity_column_au(name);
    const bool used = i == c.timestamp || i == c.success || i == c.confidence || i == c.face_id ||
                      (angles && (i == c.gaze_angle_x || i == c.gaze_angle_y)) ||
                      (vectors && name.starts_with("gaze_") && !name.starts_with("gaze_angle")) || i == c.pose[0] ||
                      i == c.pose[1] || i == c.pose[2] || name == "frame";
    if (au && !table.is_lost(std::to_string(*au)) && table.has_key(std::to_string(*au))) {
      Columns::Unit unit{i, table.rows_of(std::to_string(*au))};
      for (const vocabulary::MappingRow& row : unit.rows) drive(c.faps, {row.fap});
      c.units.push_back(std::move(unit));
    } else if (!used) {
      c.unread.push_back(name);
    }
  }
  return c;
}

// One row's FAP values (before any hold).
Result<vocabulary::FapVector> row_values(const CsvLines& lines, const std::vector<CsvCell>& cells, const Columns& c,
                                         int& clamped) {
  vocabulary::FapVector v{};
  for (const Columns::Unit& unit : c.units) {
    Result<double> r = lines.number(cells[unit.column], "action unit intensity");
    if (!r) return r.error();
    const double intensity = std::clamp(*r, 0.0, kFullIntensity);
    if (intensity != *r) ++clamped;
    for (const vocabulary::MappingRow& row : unit.rows)
      v[static_cast<std::size_t>(row.fap - 1)] += row.amount * intensity / kFullIntensity;
  }
  // Head pose (OpenFace: radians, camera axes X right, Y down, Z away from the camera, left-handed
  // positive): +Rx brings the chin toward the camera (a nod down: +head_pitch), +Ry turns the nose
  // to the image's right (the face's left: +head_yaw), +Rz lifts the face's left side (a tilt to
  // its right: +head_roll).
  const int pose_fap[3] = {48, 49, 50};
  for (int axis = 0; axis < 3; ++axis) {
    if (!c.pose[axis]) continue;
    Result<double> r = lines.number(cells[*c.pose[axis]], "head rotation");
    if (!r) return r.error();
    v[static_cast<std::size_t>(pose_fap[axis] - 1)] = *r * kRadiansToAu;
  }
  if (c.gaze_angle_x && c.gaze_angle_y) {
    // Both eyes' mean direction: +x looks to the image's right (the face's left, +yaw), +y down.
    Result<double> x = lines.number(cells[*c.gaze_angle_x], "gaze angle");
    if (!x) return x.error();
    Result<double> y = lines.number(cells[*c.gaze_angle_y], "gaze angle");
    if (!y) return y.error();
    v[22] = v[23] = *x * kRadiansToAu;
    v[24] = v[25] = *y * kRadiansToAu;
  } else if (c.gaze_vectors) {
    // 1.x: a unit vector per eye; eye 0 is the leftmost in the picture, the face's right eye.
    for (int eye = 0; eye < 2; ++eye) {
      double g[3];
      for (int axis = 0; axis < 3; ++axis) {
        Result<double> r = lines.number(cells[*c.gaze[eye][axis]], "gaze vector");
        if (!r) return r.error();
        g[axis] = *r;
      }
      const std::size_t yaw = eye == 0 ? 23 : 22, pitch = eye == 0 ? 25 : 24;
      // A vector that does not point toward the camera (OpenFace writes zeros when it has no
      // gaze) has no angle to read: the eye looks ahead.
      const double toward_camera = -g[2];
      if (toward_camera <= 1e-9) continue;
      v[yaw] = std::atan2(g[0], toward_camera) * kRadiansToAu;
      v[pitch] = std::atan2(g[1], toward_camera) * kRadiansToAu;
    }
  }
  return v;
}

}  // namespace

bool looks_like_openface(const std::vector<std::string>& header) {
  for (const std::string& name : header) {
    if (intensity_column_au(name) || (name.starts_with("AU") && name.ends_with("_c")) ||
        starts_with_any(name, {"pose_R", "gaze_angle_", "gaze_0_"}))
      return true;
  }
  return false;
}

Result<TrackRead> read_openface_csv(std::string_view text, const std::string& file, const TrackOptions& options) {
  CsvLines lines(text, file);
  Result<std::vector<std::string>> header = read_header(lines);
  if (!header) return header.error();
  Result<Columns> columns = find_columns(*header, file);
  if (!columns) return columns.error();
  const Columns& c = *columns;
  TrackRead read;
  read.frames.fps = options.fps;
  if (!c.unread.empty()) {
    read.warnings.push_back(columns_not_read(file, codes::openface::columns_not_read, c.unread,
                                             "landmarks, shape parameters, translations, AU presence and "
                                             "units without FAPs carry nothing fapc maps"));
  }
  Resampler resampler(options.fps, c.faps, options.limits, read.frames);
  std::vector<CsvCell> cells;
  std::optional<double> face;    // the face followed: the first row's face_id
  vocabulary::FapVector held{};  // the last trusted row's values (neutral before any)
  std::optional<double> last_time;
  int untrusted = 0, first_untrusted_line = 0, other_faces = 0, clamped = 0, rows = 0;
  while (lines.next(cells)) {
    if (Status width = lines.check_width(cells, header->size()); !width) return width.error();
    if (c.face_id) {
      Result<double> id = lines.number(cells[*c.face_id], "face_id");
      if (!id) return id.error();
      if (!face) face = *id;
      if (*id != *face) {
        ++other_faces;
        continue;
      }
    }
    ++rows;
    Result<double> time = lines.number(cells[c.timestamp], "timestamp");
    if (!time) return time.error();
    if (last_time && *time < *last_time) {
      return lines.error_at(codes::csv::time_backwards, &cells[c.timestamp],
                            "the timestamp goes back, from " + std::to_string(*last_time) + " to " +
                                std::string(cells[c.timestamp].text) + " s");
    }
    last_time = *time;
    bool trusted = true;
    if (c.success) {
      Result<double> success = lines.number(cells[*c.success], "success");
      if (!success) return success.error();
      trusted = *success != 0;
    }
    if (c.confidence) {
      Result<double> confidence = lines.number(cells[*c.confidence], "confidence");
      if (!confidence) return confidence.error();
      trusted = trusted && *confidence >= kMinConfidence;
    }
    Result<vocabulary::FapVector> values = row_values(lines, cells, c, clamped);
    if (!values) return values.error();
    if (trusted) {
      held = *values;
    } else if (untrusted++ == 0) {
      first_untrusted_line = lines.line();
    }
    if (Status pushed = resampler.push(*time, held, Location::text(file, lines.line(), cells[c.timestamp].column));
        !pushed)
      return pushed.error();
  }
  if (rows == 0)
    return make_error(codes::csv::no_rows, Location::text(file, lines.line(), 1),
                      "an OpenFace CSV without any data row");
  if (untrusted > 0) {
    read.warnings.push_back(make_warning(
        codes::openface::untrusted_rows, Location::text(file, first_untrusted_line, 1),
        std::to_string(untrusted) + " of " + std::to_string(rows) +
            " rows (the first here) have success 0 or a confidence below 0.5: they hold the last tracked face "
            "(the neutral face before the first)"));
  }
  if (other_faces > 0) {
    read.warnings.push_back(make_warning(codes::openface::other_faces, Location::text(file, 1, 1),
                                         std::to_string(other_faces) +
                                             " rows of other faces (face_id) are not read: fapc follows the first "
                                             "row's face"));
  }
  if (clamped > 0) {
    read.warnings.push_back(make_warning(codes::openface::intensity_clamped, Location::text(file, 1, 1),
                                         std::to_string(clamped) + " action unit intensities outside 0-5 were "
                                                                   "clamped to that range"));
  }
  return read;
}

}  // namespace fapc::pipeline::bridges

#include "arkit_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "csv_lines.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/vocabulary/arkit_shapes.hpp"
#include "fapc/vocabulary/mapping_table.hpp"
#include "resampler.hpp"

namespace fapc::pipeline::bridges {
namespace {

// The timecode rates Live Link Face can stamp; the file's is the smallest above every frame
// field it uses.
constexpr int kTimecodeRates[] = {24, 25, 30, 50, 60};

enum class Clock { timecode, seconds, milliseconds, rows };

struct Columns {
  Clock clock = Clock::rows;
  std::size_t time = 0;
  struct Shape {
    std::size_t column;
    std::vector<vocabulary::MappingRow> rows;
  };
  std::vector<Shape> shapes;
  struct Angle {
    std::size_t column;
    ArkitAngle what;
  };
  std::vector<Angle> angles;
  bool eye_angles = false;  // the eyeballs come from the angle columns, not the eyeLook shapes
  std::bitset<kFapCount> faps;
  std::vector<std::string> unread;
};

Columns find_columns(const std::vector<std::string>& header) {
  Columns c;
  for (auto [name, clock] : {std::pair{"Timecode", Clock::timecode}, std::pair{"timestamp", Clock::seconds},
                             std::pair{"time", Clock::seconds}, std::pair{"timestamp_ms", Clock::milliseconds}}) {
    if (const auto at = column_of(header, name); at && c.clock == Clock::rows) {
      c.clock = clock;
      c.time = *at;
    }
  }
  for (const ArkitAngle& angle : arkit_angle_columns()) {
    if (angle.fap >= 23 && angle.fap <= 26 && column_of(header, angle.name)) c.eye_angles = true;
  }
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string& name = header[i];
    if (c.clock != Clock::rows && i == c.time) continue;
    if (name == "BlendShapeCount" || name == "_neutral") continue;  // a count; MediaPipe's rest weight
    if (const std::optional<int> shape = vocabulary::find_arkit_shape(name)) {
      Columns::Shape s{
          i, vocabulary::arkit_table().rows_of(vocabulary::arkit_shape_names()[static_cast<std::size_t>(*shape)])};
      std::erase_if(s.rows, [&](const vocabulary::MappingRow& row) {
        return row.fap == 0 || (c.eye_angles && row.fap >= 23 && row.fap <= 26);
      });
      for (const auto& row : s.rows) c.faps.set(static_cast<std::size_t>(row.fap - 1));
      c.shapes.push_back(std::move(s));
      continue;
    }
    bool angle_found = false;
    for (const ArkitAngle& angle : arkit_angle_columns()) {
      if (name != angle.name) continue;
      angle_found = true;
      c.angles.push_back({i, angle});
      if (angle.fap) c.faps.set(static_cast<std::size_t>(angle.fap - 1));
    }
    if (!angle_found) c.unread.push_back(name);
  }
  return c;
}

int parse_two_digits(std::string_view text) {
  int value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc{} && ptr == text.data() + text.size() && text.size() == 2 ? value : -1;
}

}  // namespace

const std::array<ArkitAngle, 9>& arkit_angle_columns() {
  // The eyes' signs are measured on the corpus's takes: LeftEyeYaw follows EyeLookIn minus
  // EyeLookOut of the left eye and RightEyeYaw EyeLookOut minus EyeLookIn of the right
  // (correlation 0.98-1.0), so a positive yaw looks to the face's right (negative FAP yaw); a
  // positive pitch looks down (EyeLookDown minus EyeLookUp, 0.996-1.0). The head's are taken to
  // follow the eyes' (the corpus's takes do not record the head: all zero).
  static constexpr std::array<ArkitAngle, 9> columns{{
      {"HeadYaw", 49, -1},
      {"HeadPitch", 48, 1},
      {"HeadRoll", 50, 1},
      {"LeftEyeYaw", 23, -1},
      {"LeftEyePitch", 25, 1},
      {"LeftEyeRoll", 0, 0},
      {"RightEyeYaw", 24, -1},
      {"RightEyePitch", 26, 1},
      {"RightEyeRoll", 0, 0},
  }};
  return columns;
}

int timecode_frame_field(std::string_view text) {
  if (text.size() < 11 || text[2] != ':' || text[5] != ':' || text[8] != ':') return -1;
  return parse_two_digits(text.substr(9, 2));
}

std::optional<double> timecode_seconds(std::string_view text, int rate) {
  if (text.size() < 11 || text[2] != ':' || text[5] != ':' || text[8] != ':') return std::nullopt;
  const int h = parse_two_digits(text.substr(0, 2)), m = parse_two_digits(text.substr(3, 2)),
            s = parse_two_digits(text.substr(6, 2)), f = parse_two_digits(text.substr(9, 2));
  if (h < 0 || m < 0 || m > 59 || s < 0 || s > 59 || f < 0 || f >= rate) return std::nullopt;
  double fraction = 0;
  if (text.size() > 11) {
    const std::string_view rest = text.substr(11);
    if (rest.size() < 2 || rest[0] != '.') return std::nullopt;
    for (char ch : rest.substr(1))
      if (ch < '0' || ch > '9') return std::nullopt;
    std::from_chars(rest.data(), rest.data() + rest.size(), fraction);  // ".652": digits checked above
  }
  return (h * 60.0 + m) * 60.0 + s + (f + fraction) / rate;
}

bool looks_like_arkit(const std::vector<std::string>& header) {
  for (const std::string& name : header) {
    if (name == "Timecode" || name == "_neutral" || vocabulary::find_arkit_shape(name)) return true;
  }
  return false;
}

Result<TrackRead> read_arkit_csv(std::string_view text, const std::string& file, const TrackOptions& options) {
  CsvLines lines(text, file);
  Result<std::vector<std::string>> header = read_header(lines);
  if (!header) return header.error();
  const Columns c = find_columns(*header);
  if (c.shapes.empty()) {
    return make_error(codes::arkit::no_shape_column, Location::text(file, 1, 1),
                      "an ARKit CSV without any of the 52 shape columns");
  }
  TrackRead read;
  read.frames.fps = options.fps;
  if (!c.unread.empty()) {
    read.warnings.push_back(
        columns_not_read(file, codes::arkit::columns_not_read, c.unread, "not ARKit shapes or angles"));
  }
  // The timecode's rate: one pass over the frame fields first (a timecode by itself does not say).
  int rate = 0;
  if (c.clock == Clock::timecode) {
    CsvLines scan(text, file);
    std::vector<CsvCell> cells;
    int highest = 0;
    scan.next(cells);
    while (scan.next(cells)) {
      if (c.time < cells.size()) highest = std::max(highest, timecode_frame_field(cells[c.time].text));
    }
    for (int candidate : kTimecodeRates) {
      if (candidate > highest) {
        rate = candidate;
        break;
      }
    }
    if (rate == 0) rate = 60;  // a field beyond 59 is refused by the row's own check below
  }
  Resampler resampler(options.fps, c.faps, options.limits, read.frames);
  std::vector<CsvCell> cells;
  std::optional<double> last_time;
  int rows = 0, clamped = 0, rolled = 0;
  while (lines.next(cells)) {
    if (Status width = lines.check_width(cells, header->size()); !width) return width.error();
    double time = static_cast<double>(rows) / options.fps;
    if (c.clock == Clock::timecode) {
      const std::optional<double> seconds = timecode_seconds(cells[c.time].text, rate);
      if (!seconds) {
        return lines.error_at(codes::arkit::bad_timecode, &cells[c.time],
                              "'" + std::string(cells[c.time].text) + "' is not a timecode HH:MM:SS:FF[.fff] at " +
                                  std::to_string(rate) + " frames a second");
      }
      time = *seconds;
      // A take that runs past midnight starts again at 00: the day is added back.
      while (last_time && time < *last_time - 43200) time += 86400;
    } else if (c.clock != Clock::rows) {
      Result<double> t = lines.number(cells[c.time], (*header)[c.time]);
      if (!t) return t.error();
      time = c.clock == Clock::milliseconds ? *t / 1000 : *t;
    }
    if (last_time && time < *last_time) {
      return lines.error_at(codes::csv::time_backwards, &cells[c.time],
                            "the time goes back, to " + std::string(cells[c.time].text));
    }
    last_time = time;
    ++rows;
    vocabulary::FapVector v{};
    for (const Columns::Shape& shape : c.shapes) {
      Result<double> w = lines.number(cells[shape.column], (*header)[shape.column]);
      if (!w) return w.error();
      const double weight = std::clamp(*w, 0.0, 1.0);
      if (weight != *w) ++clamped;
      for (const auto& row : shape.rows) v[static_cast<std::size_t>(row.fap - 1)] += weight * row.amount;
    }
    for (const Columns::Angle& angle : c.angles) {
      Result<double> a = lines.number(cells[angle.column], (*header)[angle.column]);
      if (!a) return a.error();
      if (angle.what.fap == 0) {
        if (*a != 0) ++rolled;
        continue;
      }
      v[static_cast<std::size_t>(angle.what.fap - 1)] = angle.what.sign * *a * kRadiansToAu;
    }
    const std::size_t place = c.clock == Clock::rows ? 0 : c.time;
    if (Status pushed = resampler.push(time, v, Location::text(file, lines.line(), cells[place].column)); !pushed)
      return pushed.error();
  }
  if (rows == 0)
    return make_error(codes::csv::no_rows, Location::text(file, lines.line(), 1), "an ARKit CSV without any data row");
  if (clamped > 0) {
    read.warnings.push_back(make_warning(codes::arkit::weight_clamped, Location::text(file, 1, 1),
                                         std::to_string(clamped) + " shape weights outside 0-1 were clamped to it"));
  }
  if (rolled > 0) {
    read.warnings.push_back(make_warning(codes::arkit::eye_roll_lost, Location::text(file, 1, 1),
                                         std::to_string(rolled) + " eye roll values are not 0: FAPs have no eyeball "
                                                                  "roll, so they are lost"));
  }
  return read;
}

}  // namespace fapc::pipeline::bridges

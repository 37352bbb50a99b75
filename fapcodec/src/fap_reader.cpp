// The tolerant .fap reader of docs/fap-files.md: line-based, any whitespace, every variant found in
// real files, and a positioned error for anything else.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

#include "fap_text_lines.hpp"
#include "fapc/codec/codes.hpp"
#include "fapc/codec/fap_file.hpp"

namespace fapc {

namespace {

using fapfile::Line;
using fapfile::Token;

std::optional<long long> parse_integer(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  // Most tokens are short integers: read them here (no more than 18 digits cannot overflow),
  // and leave the rest, with its errors, to std::from_chars.
  if (!s.empty() && s.size() <= 18) {
    std::size_t i = s.front() == '-' ? 1 : 0;
    if (i < s.size()) {
      long long magnitude = 0;
      for (; i < s.size(); ++i) {
        const unsigned digit = static_cast<unsigned char>(s[i]) - unsigned{'0'};
        if (digit > 9) break;
        magnitude = magnitude * 10 + digit;
      }
      if (i == s.size()) return s.front() == '-' ? -magnitude : magnitude;
    }
  }
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::optional<double> parse_number(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

bool is_mask_shaped(const Line& line) {
  if (line.tokens.size() != 68 && line.tokens.size() != 69) return false;
  for (const Token& t : line.tokens)
    if (t.text != "0" && t.text != "1") return false;
  return true;
}

constexpr long long kMaxFrameNumber = 1'000'000'000'000'000;

// Field ranges of FAP 1 and FAP 2 (docs/fap-table.md section 4), in file order.
constexpr int kVisemeMax[kVisemeFieldCount] = {14, 14, 63, 1};
constexpr const char* kVisemeField[kVisemeFieldCount] = {"viseme_select1", "viseme_select2", "viseme_blend",
                                                         "viseme_def"};
constexpr int kExpressionMax[kExpressionFieldCount] = {6, 63, 6, 63, 1, 1};
constexpr const char* kExpressionField[kExpressionFieldCount] = {"expression_select1", "expression_intensity1",
                                                                 "expression_select2", "expression_intensity2",
                                                                 "init_face",          "expression_def"};

class Reader {
 public:
  Reader(std::string_view text, const std::string& file, const FapReadOptions& options, FapFrameSink sink = {},
         std::function<void(std::size_t)> progress = {})
      : lines_(text), file_(file), options_(options), sink_(std::move(sink)), progress_(std::move(progress)) {}

  Result<FapReadResult> run();
  std::vector<std::int64_t> take_numbers() { return std::move(numbers_); }

 private:
  template <class AnyLine>
  Diagnostic error_at(ErrorCode code, const AnyLine& line, int column, const std::string& message) const {
    return make_error(code, Location::text(file_, line.number, column), message, std::string(line.text));
  }
  template <class AnyLine>
  void warn_at(WarningCode code, const AnyLine& line, int column, const std::string& message) {
    out_.warnings.push_back(
        make_warning(code, Location::text(file_, line.number, column), message, std::string(line.text)));
  }
  void warn_file(WarningCode code, const std::string& message) {
    out_.warnings.push_back(make_warning(code, Location::whole_file(file_), message));
  }

  std::optional<Diagnostic> read_header(const Line& line);
  // The fast path's side of the facts: tabs and trailing blanks seen.
  void note_layout(const fapfile::IntegerLine& line);
  // A value line of integers for a mask without FAP 1/2: the frame, or false (nothing changed)
  // when the line needs the general reading (and perhaps a diagnostic).
  bool read_plain_values(const fapfile::IntegerLine& line, const std::bitset<kFapCount>& mask, FapFrame& frame);
  // A frame read: its number and line kept for placing the frames in time, the frame stored
  // or handed to the caller's sink.
  std::optional<Diagnostic> deliver(const FapFrame& frame, int line_number);
  std::optional<Diagnostic> read_mask(const Line& line, std::bitset<kFapCount>& mask);
  std::optional<Diagnostic> read_values(const Line& line, const std::bitset<kFapCount>& mask, FapFrame& frame);
  std::optional<Diagnostic> read_value(const Line& line, const Token& token, long long low, long long high,
                                       const char* field_name, int fap, std::int32_t& value);
  std::optional<Diagnostic> place_frames_in_time();

  fapfile::LineCursor lines_;
  const std::string& file_;
  const FapReadOptions& options_;
  FapReadResult out_;
  std::optional<long long> semaine_time_;
  // Per frame, its number (as written, then as placed in time) and the number of its value line,
  // for placing the frames in time and the diagnostics about it after reading.
  std::vector<std::int64_t> numbers_;
  std::vector<int> value_lines_;
  FapFrameSink sink_;  // empty: frames are kept in out_.sequence
  std::function<void(std::size_t)> progress_;
  std::size_t reported_ = 0;  // bytes last reported to progress_
  // Frame k's value line again, tokenized, with the column of its first token.
  struct FrameLine {
    int number;
    std::string_view text;
    int first_column;
  };
  FrameLine frame_line(std::size_t k) const;
  // The lines of several frames (ascending), found in one walk over the text.
  std::vector<FrameLine> frame_lines(const std::vector<std::size_t>& frames) const;
  // The header's frame count, for the warning when the file holds another number of frames.
  FrameLine header_count_at_{0, {}, 0};
  // read_plain_values' frame: the mask it last read and where that mask's values go.
  bool plain_slots_ready_ = false;
  std::bitset<kFapCount> plain_mask_;
  std::vector<std::uint8_t> plain_slots_;
  bool warned_float_ = false;
  bool warned_comment_after_header_ = false;
};

std::optional<Diagnostic> Reader::read_header(const Line& line) {
  FapFileFacts& facts = out_.facts;
  const auto& tokens = line.tokens;
  facts.has_header = true;
  facts.version = std::string(tokens.front().text);
  for (std::size_t i = 1; i + 2 < tokens.size(); ++i) {
    if (i > 1) facts.header_name += ' ';
    facts.header_name += tokens[i].text;
  }
  const Token& fps_token = tokens[tokens.size() - 2];
  const Token& count_token = tokens.back();
  const auto fps = parse_number(fps_token.text);
  // Frame rates are integers once read (docs/fap-files.md), so below 0.5 would round to 0.
  if (!fps || *fps < 0.5 || *fps > 1000)
    return error_at(codes::fap::bad_frame_rate, line, fps_token.column,
                    "header frame rate must be a number from 1 to 1000, found '" + std::string(fps_token.text) + "'");
  const auto count = parse_integer(count_token.text);
  if (!count || *count < 0)
    return error_at(codes::fap::bad_frame_count, line, count_token.column,
                    "header frame count must be a non-negative integer, found '" + std::string(count_token.text) + "'");
  facts.header_fps = *fps;
  facts.header_fps_at = Location::text(file_, line.number, fps_token.column);
  facts.header_count = *count;
  header_count_at_ = FrameLine{line.number, line.text, count_token.column};
  // Room for the frames the header announces, as far as the text can hold them (a frame takes
  // two lines, the mask alone 136 bytes) and the limit allows: no copying as they are read.
  constexpr long long kLeastFrameBytes = 138;
  const auto room =
      static_cast<std::size_t>(std::min({*count, static_cast<long long>(lines_.text_size()) / kLeastFrameBytes + 1,
                                         static_cast<long long>(options_.max_frames)}));
  if (!sink_) out_.sequence.frames.reserve(room);
  numbers_.reserve(room);
  value_lines_.reserve(room);
  out_.sequence.name = facts.header_name;
  out_.sequence.fps = static_cast<int>(std::lround(*fps));
  if (std::floor(*fps) != *fps)
    warn_at(
        codes::fap::fractional_fps, line, fps_token.column,
        "frame rate " + std::string(fps_token.text) + " is not an integer; using " + std::to_string(out_.sequence.fps));
  if (facts.version == "2.0") {
    warn_at(codes::fap::vreng_v20, line, tokens.front().column,
            options_.vreng_divide_v20 ? "version 2.0: values divided by 20 (VREng's convention, as asked)"
                                      : "version 2.0: values kept as written (VREng divides them by 20)");
  } else if (facts.version != "2.1") {
    warn_at(codes::fap::version, line, tokens.front().column,
            "version " + facts.version + " (2.1 expected); reading it as 2.1");
  }
  return std::nullopt;
}

std::optional<Diagnostic> Reader::read_mask(const Line& line, std::bitset<kFapCount>& mask) {
  const auto& tokens = line.tokens;
  if (tokens.size() == 69 && tokens.back().text == "0") {
    if (!out_.facts.mask_69_tokens)  // once per file, without the (long) source line
      out_.warnings.push_back(
          make_warning(codes::fap::mask_69_values, Location::text(file_, line.number, tokens.back().column),
                       "mask lines have 69 values (Greta's writer); the 69th, always 0, is ignored"));
    out_.facts.mask_69_tokens = true;
  } else if (tokens.size() != 68) {
    const int column = tokens.size() > 68 ? tokens[68].column : static_cast<int>(line.text.size()) + 1;
    return error_at(codes::fap::mask_length, line, column,
                    "mask line has " + std::to_string(tokens.size()) + " values; expected 68 (one 0 or 1 per FAP)");
  }
  mask.reset();
  for (std::size_t i = 0; i < kFapCount; ++i) {
    const Token& t = tokens[i];
    if (t.text == "1") {
      mask.set(i);
    } else if (t.text != "0") {
      return error_at(
          codes::fap::mask_value, line, t.column,
          "mask value for FAP " + std::to_string(i + 1) + " must be 0 or 1, found '" + std::string(t.text) + "'");
    }
  }
  return std::nullopt;
}

std::optional<Diagnostic> Reader::read_value(const Line& line, const Token& token, long long low, long long high,
                                             const char* field_name, int fap, std::int32_t& value) {
  // Named lazily: building the name for every value would dominate the reading time.
  const auto what = [&] { return fap > 0 ? "value of FAP " + std::to_string(fap) : std::string(field_name); };
  double number = 0;
  const bool scaled = options_.vreng_divide_v20 && out_.facts.version == "2.0" && fap > 0;
  if (const auto integer = parse_integer(token.text)) {
    // An integer needs no rounding: checked as it is, unless it is to be scaled.
    if (!scaled && *integer >= low && *integer <= high) {
      value = static_cast<std::int32_t>(*integer);
      return std::nullopt;
    }
    number = static_cast<double>(*integer);
  } else if (const auto real = parse_number(token.text)) {
    number = *real;
    if (!warned_float_)
      warn_at(codes::fap::value, line, token.column,
              "value '" + std::string(token.text) + "' is not an integer; values are rounded half away from zero");
    warned_float_ = true;
    out_.facts.float_values = true;
  } else {
    return error_at(codes::fap::not_a_number, line, token.column,
                    what() + " must be a number, found '" + std::string(token.text) + "'");
  }
  // VREng's private scaling applies to FAP values, not to the viseme and expression fields.
  if (scaled) number /= 20;
  const double rounded = std::round(number);  // std::round: halves away from zero
  if (rounded < static_cast<double>(low) || rounded > static_cast<double>(high))
    return error_at(
        codes::fap::value_out_of_range, line, token.column,
        what() + " " + std::string(token.text) + " is outside " + std::to_string(low) + ".." + std::to_string(high));
  value = static_cast<std::int32_t>(rounded);
  return std::nullopt;
}

std::optional<Diagnostic> Reader::read_values(const Line& line, const std::bitset<kFapCount>& mask, FapFrame& frame) {
  const auto& tokens = line.tokens;
  const auto number = parse_integer(tokens.front().text);
  if (!number)
    return error_at(
        codes::fap::bad_frame_number, line, tokens.front().column,
        "a value line must start with an integer frame number, found '" + std::string(tokens.front().text) + "'");
  // Bounded before any arithmetic on it (gaps, millisecond grids, renumbering): 10^15 is 31,000
  // years of millisecond stamps, and differences of such numbers cannot overflow.
  if (*number > kMaxFrameNumber || *number < -kMaxFrameNumber)
    return error_at(codes::fap::frame_number_out_of_range, line, tokens.front().column,
                    "frame number " + std::string(tokens.front().text) + " is outside -" +
                        std::to_string(kMaxFrameNumber) + ".." + std::to_string(kMaxFrameNumber));
  frame.number = *number;
  frame.mask = mask;
  const bool fap1 = mask.test(0), fap2 = mask.test(1);
  const std::size_t low_level = mask.count() - (fap1 ? 1 : 0) - (fap2 ? 1 : 0);
  const std::size_t single = mask.count();
  const std::size_t full = low_level + (fap1 ? kVisemeFieldCount : 0) + (fap2 ? kExpressionFieldCount : 0);
  const std::size_t given = tokens.size() - 1;
  bool full_fields = false;
  if (given == full) {
    full_fields = true;
    if (fap1 || fap2) out_.facts.fap12_full_fields = true;
  } else if (given == single) {
    out_.facts.fap12_single_values = true;
  } else {
    const std::string expected = full == single ? std::to_string(full)
                                                : std::to_string(full) + " (FAP 1 as 4 and FAP 2 as 6 values) or " +
                                                      std::to_string(single) + " (one value each)";
    const int column = given > full ? tokens[full + 1].column : static_cast<int>(line.text.size()) + 1;
    return error_at(
        codes::fap::value_count, line, column,
        "value line has " + std::to_string(given) + " values after the frame number; its mask needs " + expected);
  }
  std::size_t next = 1;
  std::int32_t field = 0;
  if (fap1) {
    int* fields[kVisemeFieldCount] = {&frame.viseme.select1, &frame.viseme.select2, &frame.viseme.blend,
                                      &frame.viseme.def};
    // A single viseme value is taken as viseme_select1 shown alone (blend 63): Greta's form.
    const int count = full_fields ? kVisemeFieldCount : 1;
    for (int k = 0; k < count; ++k) {
      if (auto e = read_value(line, tokens[next++], 0, kVisemeMax[k], kVisemeField[k], 0, field)) return e;
      *fields[k] = field;
    }
    if (!full_fields) frame.viseme.blend = 63;
  }
  if (fap2) {
    int* fields[kExpressionFieldCount] = {&frame.expression.select1,   &frame.expression.intensity1,
                                          &frame.expression.select2,   &frame.expression.intensity2,
                                          &frame.expression.init_face, &frame.expression.def};
    // A single expression value is taken as expression_select1 at full intensity.
    const int count = full_fields ? kExpressionFieldCount : 1;
    for (int k = 0; k < count; ++k) {
      if (auto e = read_value(line, tokens[next++], 0, kExpressionMax[k], kExpressionField[k], 0, field)) return e;
      *fields[k] = field;
    }
    if (!full_fields) frame.expression.intensity1 = 63;
  }
  for (int fap = 3; fap <= kFapCount; ++fap) {
    if (!frame.has(fap)) continue;
    constexpr long long kLimit = std::numeric_limits<std::int32_t>::max();
    if (auto e = read_value(line, tokens[next++], -kLimit, kLimit, nullptr, fap, field)) return e;
    frame.values[static_cast<std::size_t>(fap - 1)] = field;
  }
  return std::nullopt;
}

// docs/fap-files.md section 6: what the frame numbers mean.
std::optional<Diagnostic> Reader::place_frames_in_time() {
  auto& frames = numbers_;
  FapFileFacts& facts = out_.facts;
  for (std::size_t i = 1; i < frames.size(); ++i)
    if (frames[i] <= frames[i - 1]) {
      const FrameLine line = frame_line(i);
      return error_at(codes::fap::frame_order, line, line.first_column,
                      "frame number " + std::to_string(frames[i]) + " does not follow frame " +
                          std::to_string(frames[i - 1]) + "; frame numbers must ascend");
    }
  if (frames.empty()) return std::nullopt;

  long long step = 0;  // the smallest gap between consecutive numbers
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const long long gap = frames[i] - frames[i - 1];
    step = step == 0 ? gap : std::min(step, gap);
  }
  const bool stamps = !facts.has_header && (semaine_time_ || (step > 1 && 1000 % step == 0));
  if (stamps) {
    if (step == 0) step = semaine_time_ ? frames.front() - *semaine_time_ : 40;
    if (step <= 0 || 1000 % step != 0) step = 40;  // SEMAINE's grid (25 fps)
    facts.millisecond_stamps = true;
    out_.sequence.fps = static_cast<int>(1000 / step);
    const long long first = frames.front();
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const long long offset = frames[i] - first;
      if (offset % step != 0) {
        const FrameLine line = frame_line(i);
        return error_at(codes::fap::off_grid, line, line.first_column,
                        "time stamp " + std::to_string(frames[i]) + " ms is not on the " + std::to_string(step) +
                            " ms grid of the first frame");
      }
      frames[i] = offset / step;
    }
    warn_file({"fap.no_header"}, "no header; frame numbers read as millisecond time stamps (" +
                                     std::to_string(out_.sequence.fps) + " fps, first frame at " +
                                     std::to_string(first) + " ms taken as time 0)");
  } else if (!facts.has_header) {
    out_.sequence.fps = options_.headerless_fps;
    warn_file({"fap.no_header"}, "no header; assuming " + std::to_string(options_.headerless_fps) + " fps");
  }
  // Writers fill gaps and the Algebra allocates a slot per frame: the span is what costs.
  for (std::size_t i = 1; i < frames.size(); ++i)
    if (frames[i] - frames.front() >= options_.max_frames) {
      const FrameLine line = frame_line(i);
      Limits limits;
      limits.max_frames = options_.max_frames;
      return limit_error(Location::text(file_, line.number, line.first_column),
                         "frames " + std::to_string(frames.front()) + " to " + std::to_string(frames[i]) + " span " +
                             std::to_string(frames[i] - frames.front() + 1) + " frames",
                         Limit::frames, limits);
    }
  if (facts.has_header && frames.front() == 1 && frames.back() == static_cast<long long>(frames.size())) {
    facts.frames_from_one = true;
    for (std::int64_t& number : frames) --number;
    warn_file({"fap.numbered_from_1"}, "frames are numbered from 1; renumbered from 0");
  }
  std::vector<std::size_t> after_gap;
  for (std::size_t i = 1; i < frames.size(); ++i)
    if (frames[i] != frames[i - 1] + 1) after_gap.push_back(i);
  facts.frame_gaps = !after_gap.empty();
  const std::vector<FrameLine> lines = frame_lines(after_gap);
  for (std::size_t g = 0; g < after_gap.size(); ++g) {
    const std::size_t i = after_gap[g];
    warn_at(codes::fap::missing_frames, lines[g], lines[g].first_column,
            "frames " + std::to_string(frames[i - 1] + 1) + " to " + std::to_string(frames[i] - 1) + " are absent");
  }
  return std::nullopt;
}

std::optional<Diagnostic> Reader::deliver(const FapFrame& frame, int line_number) {
  if (frame.mask.none()) out_.facts.zero_active_faps = true;
  numbers_.push_back(frame.number);
  value_lines_.push_back(line_number);
  if (!sink_) {
    out_.sequence.frames.push_back(frame);
    return std::nullopt;
  }
  if (auto status = sink_(frame); !status) return status.error();
  return std::nullopt;
}

void Reader::note_layout(const fapfile::IntegerLine& line) {
  if (line.has_tab) out_.facts.tabs = true;
  if (line.trailing_blank) out_.facts.trailing_spaces = true;
}

bool Reader::read_plain_values(const fapfile::IntegerLine& line, const std::bitset<kFapCount>& mask, FapFrame& frame) {
  // FAP 1/2 fields, counts that do not match the mask and values out of range go the general way.
  if (mask.test(0) || mask.test(1) || static_cast<std::size_t>(line.count - 1) != mask.count()) return false;
  const long long number = line.values[0];
  if (number > kMaxFrameNumber || number < -kMaxFrameNumber) return false;
  constexpr long long kLimit = std::numeric_limits<std::int32_t>::max();
  for (int k = 1; k < line.count; ++k)
    if (line.values[static_cast<std::size_t>(k)] > kLimit || line.values[static_cast<std::size_t>(k)] < -kLimit)
      return false;
  // The masked FAPs' places, found again only when the mask changes (`frame` is the same frame
  // each time: its other values are still 0 from then).
  if (!plain_slots_ready_ || mask != plain_mask_) {
    frame.values = {};
    plain_mask_ = mask;
    plain_slots_.clear();
    for (std::size_t i = 2; i < kFapCount; ++i)  // FAP 3 on
      if (mask[i]) plain_slots_.push_back(static_cast<std::uint8_t>(i));
    plain_slots_ready_ = true;
  }
  frame.number = number;
  frame.mask = mask;
  for (std::size_t k = 0; k < plain_slots_.size(); ++k)
    frame.values[plain_slots_[k]] = static_cast<std::int32_t>(line.values[k + 1]);
  return true;
}

Reader::FrameLine Reader::frame_line(std::size_t k) const { return frame_lines({k}).front(); }

std::vector<Reader::FrameLine> Reader::frame_lines(const std::vector<std::size_t>& frames) const {
  std::vector<FrameLine> found;
  found.reserve(frames.size());
  fapfile::LineCursor again = lines_.from_start();
  fapfile::RawLine raw{0, {}};
  fapfile::Line line;
  for (const std::size_t k : frames) {
    while (raw.number < value_lines_[k] && again.next(raw)) {
    }
    fapfile::tokenize(raw, line);
    found.push_back(FrameLine{raw.number, raw.text, line.tokens.empty() ? 1 : line.tokens.front().column});
  }
  return found;
}

Result<FapReadResult> Reader::run() {
  FapFileFacts& facts = out_.facts;
  facts.utf8_bom = lines_.utf8_bom();
  facts.final_newline = lines_.final_newline();

  enum class Expect { header, mask, values } expect = Expect::header;
  std::bitset<kFapCount> mask;
  fapfile::RawLine mask_line{0, {}};
  Line line;
  line.tokens.reserve(72);  // a mask line has 68 or 69 tokens
  // Lines of integers that need no diagnostic are read on a fast path (fast_line); any other line,
  // and any line the fast path doubts, is tokenized and read in full.
  fapfile::IntegerLine integers;
  FapFrame plain;
  const bool scaled_values = options_.vreng_divide_v20;
  for (fapfile::RawLine raw{0, {}}; lines_.next(raw);) {
    constexpr std::size_t kReportEvery = std::size_t{16} << 20;
    if (progress_ && lines_.offset() - reported_ >= kReportEvery) progress_(reported_ = lines_.offset());
    if (bool trailing = false; expect == Expect::mask && fapfile::scan_plain_mask(raw.text, mask, trailing)) {
      if (trailing) out_.facts.trailing_spaces = true;
      mask_line = raw;
      expect = Expect::values;
      continue;
    }
    if (expect == Expect::mask && fapfile::scan_integers(raw.text, integers, lines_.text_end()) &&
        integers.count == 68 && integers.bits) {
      mask.reset();
      for (std::size_t i = 0; i < kFapCount; ++i) mask[i] = integers.values[i] != 0;
      note_layout(integers);
      mask_line = raw;
      expect = Expect::values;
      continue;
    }
    if (expect == Expect::values && !scaled_values && fapfile::scan_integers(raw.text, integers, lines_.text_end()) &&
        read_plain_values(integers, mask, plain)) {
      note_layout(integers);
      if (auto e = deliver(plain, raw.number)) return *e;
      expect = Expect::mask;
      continue;
    }
    fapfile::tokenize(raw, line);
    if (line.tokens.empty()) continue;  // blank lines carry nothing
    if (line.first_is_comment()) {
      ++facts.comment_lines;
      if (expect != Expect::header && !warned_comment_after_header_) {
        warn_at(codes::fap::comment_after_header, line, line.tokens.front().column,
                "comment line after the header (Xface and Greta's Java reader cannot read it)");
        warned_comment_after_header_ = true;
      }
      continue;
    }
    if (line.has_tab && expect != Expect::header) facts.tabs = true;
    if (line.trailing_blank) facts.trailing_spaces = true;
    if (expect == Expect::header) {
      expect = Expect::mask;
      if (line.tokens.size() >= 4 && parse_number(line.tokens.front().text) && !is_mask_shaped(line)) {
        if (auto e = read_header(line)) return *e;
        continue;
      }
      if (line.tokens.size() == 1 && parse_integer(line.tokens.front().text)) {
        semaine_time_ = parse_integer(line.tokens.front().text);
        facts.semaine_time_line = true;
        continue;
      }
      // No header: this line is the first mask.
    }
    if (expect == Expect::mask) {
      if (auto e = read_mask(line, mask)) return *e;
      mask_line = raw;
      expect = Expect::values;
    } else {
      FapFrame frame;
      if (auto e = read_values(line, mask, frame)) return *e;
      if (auto e = deliver(frame, line.number)) return *e;
      expect = Expect::mask;
    }
  }
  facts.crlf = lines_.crlf();
  if (expect == Expect::values)
    return error_at(codes::fap::mask_without_values, mask_line, static_cast<int>(mask_line.text.size()) + 1,
                    "mask line without the value line that must follow it");
  if (auto e = place_frames_in_time()) return *e;
  // The frames carry their numbers as written; only stamps and numbering from 1 changed them (a
  // walk over every frame, which a long file does not pay for otherwise).
  if (facts.millisecond_stamps || facts.frames_from_one)
    for (std::size_t k = 0; k < out_.sequence.frames.size(); ++k) out_.sequence.frames[k].number = numbers_[k];
  const auto frames = static_cast<long long>(numbers_.size());
  if (facts.has_header && facts.header_count != frames)
    warn_at(codes::fap::frame_count, header_count_at_, header_count_at_.first_column,
            "header says " + std::to_string(facts.header_count) + " frames, file has " + std::to_string(frames));
  if (frames == 0) warn_file(codes::fap::no_frames, "file has no frames");
  if (out_.sequence.name.empty()) out_.sequence.name = file_;
  out_.value_lines = std::move(value_lines_);
  return std::move(out_);
}

}  // namespace

Result<FapReadResult> read_fap_text(std::string_view text, const std::string& file, const FapReadOptions& options,
                                    const std::function<void(std::size_t)>& progress) {
  return Reader(text, file, options, {}, progress).run();
}

Result<FapScanResult> scan_fap_text(std::string_view text, const std::string& file, const FapReadOptions& options,
                                    const FapFrameSink& sink, const std::function<void(std::size_t)>& progress) {
  Reader reader(text, file, options, sink, progress);
  auto read = reader.run();
  if (!read) return read.error();
  return FapScanResult{std::move(*read), reader.take_numbers()};
}

}  // namespace fapc

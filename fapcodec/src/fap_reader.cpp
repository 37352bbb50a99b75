// The tolerant .fap reader of docs/fap-files.md: line-based, any whitespace, every variant found in
// real files, and a positioned error for anything else.
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

#include "fap_text_lines.hpp"
#include "fapc/codec/fap_file.hpp"

namespace fapc {

namespace {

using fapfile::Line;
using fapfile::Token;

std::optional<long long> parse_integer(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
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
constexpr const char* kVisemeField[kVisemeFieldCount] = {"viseme_select1", "viseme_select2",
                                                         "viseme_blend", "viseme_def"};
constexpr int kExpressionMax[kExpressionFieldCount] = {6, 63, 6, 63, 1, 1};
constexpr const char* kExpressionField[kExpressionFieldCount] = {
    "expression_select1", "expression_intensity1", "expression_select2",
    "expression_intensity2", "init_face", "expression_def"};

class Reader {
 public:
  Reader(std::string_view text, const std::string& file, const FapReadOptions& options)
      : split_(fapfile::split_lines(text)), file_(file), options_(options) {}

  Result<FapReadResult> run();

 private:
  template <class AnyLine>
  Diagnostic error_at(const AnyLine& line, int column, const std::string& message) const {
    return make_error(Location::text(file_, line.number, column), message, std::string(line.text));
  }
  template <class AnyLine>
  void warn_at(WarningCode code, const AnyLine& line, int column, const std::string& message) {
    out_.warnings.push_back(
        make_warning(code, Location::text(file_, line.number, column), message, std::string(line.text)));
  }
  void warn_file(WarningCode code, const std::string& message) {
    out_.warnings.push_back(make_warning(code, Location{file_, 0, 0, -1}, message));
  }

  std::optional<Diagnostic> read_header(const Line& line);
  std::optional<Diagnostic> read_mask(const Line& line, std::bitset<kFapCount>& mask);
  std::optional<Diagnostic> read_values(const Line& line, const std::bitset<kFapCount>& mask,
                                        FapFrame& frame);
  std::optional<Diagnostic> read_value(const Line& line, const Token& token, long long low,
                                       long long high, const char* field_name, int fap,
                                       std::int32_t& value);
  std::optional<Diagnostic> place_frames_in_time();

  fapfile::SplitText split_;
  const std::string& file_;
  const FapReadOptions& options_;
  FapReadResult out_;
  std::optional<long long> semaine_time_;
  // Per frame, where its value line is, for the timing diagnostics after reading.
  struct FrameLine {
    int number;
    std::string_view text;
    int first_column;
  };
  std::vector<FrameLine> value_lines_;
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
    return error_at(line, fps_token.column,
                    "header frame rate must be a number from 1 to 1000, found '" +
                        std::string(fps_token.text) + "'");
  const auto count = parse_integer(count_token.text);
  if (!count || *count < 0)
    return error_at(line, count_token.column,
                    "header frame count must be a non-negative integer, found '" +
                        std::string(count_token.text) + "'");
  facts.header_fps = *fps;
  facts.header_count = *count;
  out_.sequence.name = facts.header_name;
  out_.sequence.fps = static_cast<int>(std::lround(*fps));
  if (std::floor(*fps) != *fps)
    warn_at({"fap.fractional_fps"}, line, fps_token.column,
            "frame rate " + std::string(fps_token.text) + " is not an integer; using " +
                std::to_string(out_.sequence.fps));
  if (facts.version == "2.0") {
    warn_at({"fap.vreng_v20"}, line, tokens.front().column,
            options_.vreng_divide_v20
                ? "version 2.0: values divided by 20 (VREng's convention, as asked)"
                : "version 2.0: values kept as written (VREng divides them by 20)");
  } else if (facts.version != "2.1") {
    warn_at({"fap.version"}, line, tokens.front().column,
            "version " + facts.version + " (2.1 expected); reading it as 2.1");
  }
  return std::nullopt;
}

std::optional<Diagnostic> Reader::read_mask(const Line& line, std::bitset<kFapCount>& mask) {
  const auto& tokens = line.tokens;
  if (tokens.size() == 69 && tokens.back().text == "0") {
    if (!out_.facts.mask_69_tokens)  // once per file, without the (long) source line
      out_.warnings.push_back(make_warning({"fap.mask_69_values"},
          Location::text(file_, line.number, tokens.back().column),
          "mask lines have 69 values (Greta's writer); the 69th, always 0, is ignored"));
    out_.facts.mask_69_tokens = true;
  } else if (tokens.size() != 68) {
    const int column = tokens.size() > 68 ? tokens[68].column
                                          : static_cast<int>(line.text.size()) + 1;
    return error_at(line, column,
                    "mask line has " + std::to_string(tokens.size()) +
                        " values; expected 68 (one 0 or 1 per FAP)");
  }
  mask.reset();
  for (std::size_t i = 0; i < kFapCount; ++i) {
    const Token& t = tokens[i];
    if (t.text == "1") {
      mask.set(i);
    } else if (t.text != "0") {
      return error_at(line, t.column,
                      "mask value for FAP " + std::to_string(i + 1) + " must be 0 or 1, found '" +
                          std::string(t.text) + "'");
    }
  }
  return std::nullopt;
}

std::optional<Diagnostic> Reader::read_value(const Line& line, const Token& token, long long low,
                                             long long high, const char* field_name, int fap,
                                             std::int32_t& value) {
  // Named lazily: building the name for every value would dominate the reading time.
  const auto what = [&] {
    return fap > 0 ? "value of FAP " + std::to_string(fap) : std::string(field_name);
  };
  double number = 0;
  if (const auto integer = parse_integer(token.text)) {
    number = static_cast<double>(*integer);
  } else if (const auto real = parse_number(token.text)) {
    number = *real;
    if (!warned_float_)
      warn_at({"fap.value"}, line, token.column,
              "value '" + std::string(token.text) +
                  "' is not an integer; values are rounded half away from zero");
    warned_float_ = true;
    out_.facts.float_values = true;
  } else {
    return error_at(line, token.column,
                    what() + " must be a number, found '" + std::string(token.text) + "'");
  }
  // VREng's private scaling applies to FAP values, not to the viseme and expression fields.
  if (options_.vreng_divide_v20 && out_.facts.version == "2.0" && fap > 0) number /= 20;
  const double rounded = std::round(number);  // std::round: halves away from zero
  if (rounded < static_cast<double>(low) || rounded > static_cast<double>(high))
    return error_at(line, token.column,
                    what() + " " + std::string(token.text) + " is outside " +
                        std::to_string(low) + ".." + std::to_string(high));
  value = static_cast<std::int32_t>(rounded);
  return std::nullopt;
}

std::optional<Diagnostic> Reader::read_values(const Line& line,
                                              const std::bitset<kFapCount>& mask,
                                              FapFrame& frame) {
  const auto& tokens = line.tokens;
  const auto number = parse_integer(tokens.front().text);
  if (!number)
    return error_at(line, tokens.front().column,
                    "a value line must start with an integer frame number, found '" +
                        std::string(tokens.front().text) + "'");
  // Bounded before any arithmetic on it (gaps, millisecond grids, renumbering): 10^15 is 31,000
  // years of millisecond stamps, and differences of such numbers cannot overflow.
  if (*number > kMaxFrameNumber || *number < -kMaxFrameNumber)
    return error_at(line, tokens.front().column,
                    "frame number " + std::string(tokens.front().text) + " is outside -" +
                        std::to_string(kMaxFrameNumber) + ".." + std::to_string(kMaxFrameNumber));
  frame.number = *number;
  frame.mask = mask;
  const bool fap1 = mask.test(0), fap2 = mask.test(1);
  const std::size_t low_level = mask.count() - (fap1 ? 1 : 0) - (fap2 ? 1 : 0);
  const std::size_t single = mask.count();
  const std::size_t full = low_level + (fap1 ? kVisemeFieldCount : 0) +
                           (fap2 ? kExpressionFieldCount : 0);
  const std::size_t given = tokens.size() - 1;
  bool full_fields = false;
  if (given == full) {
    full_fields = true;
    if (fap1 || fap2) out_.facts.fap12_full_fields = true;
  } else if (given == single) {
    out_.facts.fap12_single_values = true;
  } else {
    const std::string expected =
        full == single ? std::to_string(full)
                       : std::to_string(full) + " (FAP 1 as 4 and FAP 2 as 6 values) or " +
                             std::to_string(single) + " (one value each)";
    const int column = given > full ? tokens[full + 1].column
                                    : static_cast<int>(line.text.size()) + 1;
    return error_at(line, column,
                    "value line has " + std::to_string(given) +
                        " values after the frame number; its mask needs " + expected);
  }
  std::size_t next = 1;
  std::int32_t field = 0;
  if (fap1) {
    int* fields[kVisemeFieldCount] = {&frame.viseme.select1, &frame.viseme.select2,
                                      &frame.viseme.blend, &frame.viseme.def};
    // A single viseme value is taken as viseme_select1 shown alone (blend 63): Greta's form.
    const int count = full_fields ? kVisemeFieldCount : 1;
    for (int k = 0; k < count; ++k) {
      if (auto e = read_value(line, tokens[next++], 0, kVisemeMax[k], kVisemeField[k], 0,
                                field))
        return e;
      *fields[k] = field;
    }
    if (!full_fields) frame.viseme.blend = 63;
  }
  if (fap2) {
    int* fields[kExpressionFieldCount] = {&frame.expression.select1, &frame.expression.intensity1,
                                          &frame.expression.select2, &frame.expression.intensity2,
                                          &frame.expression.init_face, &frame.expression.def};
    // A single expression value is taken as expression_select1 at full intensity.
    const int count = full_fields ? kExpressionFieldCount : 1;
    for (int k = 0; k < count; ++k) {
      if (auto e = read_value(line, tokens[next++], 0, kExpressionMax[k], kExpressionField[k],
                              0, field))
        return e;
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
  auto& frames = out_.sequence.frames;
  FapFileFacts& facts = out_.facts;
  for (std::size_t i = 1; i < frames.size(); ++i)
    if (frames[i].number <= frames[i - 1].number) {
      const FrameLine& line = value_lines_[i];
      return error_at(line, line.first_column,
                      "frame number " + std::to_string(frames[i].number) +
                          " does not follow frame " + std::to_string(frames[i - 1].number) +
                          "; frame numbers must ascend");
    }
  if (frames.empty()) return std::nullopt;

  long long step = 0;  // the smallest gap between consecutive numbers
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const long long gap = frames[i].number - frames[i - 1].number;
    step = step == 0 ? gap : std::min(step, gap);
  }
  const bool stamps = !facts.has_header && (semaine_time_ || (step > 1 && 1000 % step == 0));
  if (stamps) {
    if (step == 0) step = semaine_time_ ? frames.front().number - *semaine_time_ : 40;
    if (step <= 0 || 1000 % step != 0) step = 40;  // SEMAINE's grid (25 fps)
    facts.millisecond_stamps = true;
    out_.sequence.fps = static_cast<int>(1000 / step);
    const long long first = frames.front().number;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const long long offset = frames[i].number - first;
      if (offset % step != 0) {
        const FrameLine& line = value_lines_[i];
        return error_at(line, line.first_column,
                        "time stamp " + std::to_string(frames[i].number) + " ms is not on the " +
                            std::to_string(step) + " ms grid of the first frame");
      }
      frames[i].number = offset / step;
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
    if (frames[i].number - frames.front().number >= options_.max_frames) {
      const FrameLine& line = value_lines_[i];
      Limits limits;
      limits.max_frames = options_.max_frames;
      return limit_error(Location::text(file_, line.number, line.first_column),
                         "frames " + std::to_string(frames.front().number) + " to " +
                             std::to_string(frames[i].number) + " span " +
                             std::to_string(frames[i].number - frames.front().number + 1) + " frames",
                         Limit::frames, limits);
    }
  if (facts.has_header && frames.front().number == 1 &&
      frames.back().number == static_cast<long long>(frames.size())) {
    facts.frames_from_one = true;
    for (FapFrame& f : frames) --f.number;
    warn_file({"fap.numbered_from_1"}, "frames are numbered from 1; renumbered from 0");
  }
  for (std::size_t i = 1; i < frames.size(); ++i)
    if (frames[i].number != frames[i - 1].number + 1) {
      facts.frame_gaps = true;
      const FrameLine& line = value_lines_[i];
      warn_at({"fap.missing_frames"}, line, line.first_column,
              "frames " + std::to_string(frames[i - 1].number + 1) + " to " +
                  std::to_string(frames[i].number - 1) + " are absent");
    }
  return std::nullopt;
}

Result<FapReadResult> Reader::run() {
  FapFileFacts& facts = out_.facts;
  facts.crlf = split_.crlf;
  facts.final_newline = split_.final_newline;
  facts.utf8_bom = split_.utf8_bom;

  enum class Expect { header, mask, values } expect = Expect::header;
  std::bitset<kFapCount> mask;
  fapfile::RawLine mask_line{0, {}};
  out_.sequence.frames.reserve(split_.lines.size() / 2);
  Line line;
  line.tokens.reserve(72);  // a mask line has 68 or 69 tokens
  for (const fapfile::RawLine& raw : split_.lines) {
    fapfile::tokenize(raw, line);
    if (line.tokens.empty()) continue;  // blank lines carry nothing
    if (line.first_is_comment()) {
      ++facts.comment_lines;
      if (expect != Expect::header && !warned_comment_after_header_) {
        warn_at({"fap.comment_after_header"}, line, line.tokens.front().column,
                "comment line after the header (Xface and Greta's Java reader cannot read it)");
        warned_comment_after_header_ = true;
      }
      continue;
    }
    if (line.has_tab && expect != Expect::header) facts.tabs = true;
    if (line.trailing_blank) facts.trailing_spaces = true;
    if (expect == Expect::header) {
      expect = Expect::mask;
      if (line.tokens.size() >= 4 && parse_number(line.tokens.front().text) &&
          !is_mask_shaped(line)) {
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
      if (frame.mask.none()) facts.zero_active_faps = true;
      out_.sequence.frames.push_back(frame);
      value_lines_.push_back(FrameLine{line.number, line.text, line.tokens.front().column});
      expect = Expect::mask;
    }
  }
  if (expect == Expect::values)
    return error_at(mask_line, static_cast<int>(mask_line.text.size()) + 1,
                    "mask line without the value line that must follow it");
  if (auto e = place_frames_in_time()) return *e;
  const auto frames = static_cast<long long>(out_.sequence.frames.size());
  if (facts.has_header && facts.header_count != frames)
    warn_file({"fap.frame_count"}, "header says " + std::to_string(facts.header_count) + " frames, file has " +
              std::to_string(frames));
  if (frames == 0) warn_file({"fap.no_frames"}, "file has no frames");
  if (out_.sequence.name.empty()) out_.sequence.name = file_;
  return std::move(out_);
}

}  // namespace

Result<FapReadResult> read_fap_text(std::string_view text, const std::string& file,
                                    const FapReadOptions& options) {
  return Reader(text, file, options).run();
}

}  // namespace fapc

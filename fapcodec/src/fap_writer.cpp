// The .fap writer: the safe form every known reader accepts (docs/fap-files.md section 5), and
// the flavour of each player family (docs/fap-files.md, "Flavours").
#include <array>
#include <charconv>
#include <string>

#include "fapc/codec/codes.hpp"
#include "fapc/codec/fap_file.hpp"

namespace fapc {

namespace {

// What distinguishes the flavours, from each family's reader (docs/fap-files.md section 3).
struct Layout {
  bool header;               // `2.1 <name> <fps> <n>`; SEMAINE messages have none
  int mask_tokens;           // 68, or 69 with a final 0 (Greta's Java writer and reader)
  bool single_fap12;         // FAP 1 and FAP 2 as one value each instead of 4 and 6 fields
  bool millisecond_numbers;  // frame numbers are times in ms, after a leading time line
};

Layout layout_of(FapFlavour flavour) {
  switch (flavour) {
    case FapFlavour::safe:
    case FapFlavour::xface:
    case FapFlavour::greta_cpp:
      return {true, 68, false, false};
    case FapFlavour::greta_java:
      return {true, 69, true, false};
    case FapFlavour::vreng:
      return {true, 68, true, false};
    case FapFlavour::semaine:
      return {false, 68, true, true};
  }
  return {true, 68, false, false};
}

constexpr std::array<std::pair<FapFlavour, std::string_view>, 6> kFlavourNames{{
    {FapFlavour::safe, "safe"},
    {FapFlavour::xface, "xface"},
    {FapFlavour::greta_cpp, "greta-cpp"},
    {FapFlavour::greta_java, "greta-java"},
    {FapFlavour::vreng, "vreng"},
    {FapFlavour::semaine, "semaine"},
}};

// The single value of FAP 1 and FAP 2 means one select shown alone (fapc's reader, and Greta's
// own writer, which has no other fields): these are the only records that form can carry.
bool single_viseme(const VisemeFields& v) { return v.select2 == 0 && v.blend == 63 && v.def == 0; }
bool single_expression(const ExpressionFields& e) {
  return e.intensity1 == 63 && e.select2 == 0 && e.intensity2 == 0 && e.init_face == 0 && e.def == 0;
}

// A frame's two lines, made in a buffer as long as they can be and appended at once: appending
// value by value cost half of the writing. Each value is followed by a space; a line's last space
// is dropped when the options ask for no trailing space.
void append_frame(std::string& out, const FapFrame& frame, long long number, const Layout& layout,
                  const FapWriteOptions& options) {
  constexpr std::size_t kLongestInt = 20;  // "-9223372036854775808"
  constexpr std::size_t kMost =
      2 * (kFapCount + 1) + 1 + (1 + kVisemeFieldCount + kExpressionFieldCount + kFapCount) * (kLongestInt + 1) + 1;
  char buffer[kMost];
  char* at = buffer;
  const auto put = [&](long long v) {
    at = std::to_chars(at, buffer + kMost, v).ptr;
    *at++ = ' ';
  };
  const auto end_line = [&] {
    if (!options.trailing_space) --at;  // every line has a value, so ends with a space
    *at++ = '\n';
  };
  for (std::size_t i = 0; i < kFapCount; ++i) {
    *at++ = frame.mask.test(i) ? '1' : '0';
    *at++ = ' ';
  }
  if (layout.mask_tokens == kFapCount + 1) put(0);
  end_line();
  put(number);
  if (frame.has(1)) {
    const VisemeFields& v = frame.viseme;
    if (layout.single_fap12)
      put(v.select1);
    else
      for (int x : {v.select1, v.select2, v.blend, v.def}) put(x);
  }
  if (frame.has(2)) {
    const ExpressionFields& e = frame.expression;
    if (layout.single_fap12)
      put(e.select1);
    else
      for (int x : {e.select1, e.intensity1, e.select2, e.intensity2, e.init_face, e.def}) put(x);
  }
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (frame.has(fap)) put(frame.value(fap));
  end_line();
  out.append(buffer, at);
}

Diagnostic cannot_carry(FapFlavour flavour, const std::string& what) {
  return make_error(codes::fap::flavour_cannot_carry, Location{},
                    "the " + std::string(fap_flavour_name(flavour)) + " .fap flavour cannot carry " + what);
}

std::optional<Diagnostic> check_rate(int fps, FapFlavour flavour, const Layout& layout) {
  if (layout.millisecond_numbers && (fps <= 0 || 1000 % fps != 0))
    return cannot_carry(flavour, std::to_string(fps) +
                                     " frames per second: it numbers frames in whole milliseconds (25 fps, Greta's "
                                     "rate, is 40 ms a frame)");
  return std::nullopt;
}

std::optional<Diagnostic> check_frame(const FapFrame& frame, FapFlavour flavour, const Layout& layout) {
  if (!layout.single_fap12 ||
      ((!frame.has(1) || single_viseme(frame.viseme)) && (!frame.has(2) || single_expression(frame.expression))))
    return std::nullopt;
  {
    const auto at = "frame " + std::to_string(frame.number) + ": ";
    if (frame.has(1) && !single_viseme(frame.viseme))
      return cannot_carry(flavour, at +
                                       "FAP 1 is one value there (viseme_select1 shown alone, blend 63); this "
                                       "viseme record needs the safe, xface or greta-cpp flavour, or FAP 1 masked off");
    if (frame.has(2) && !single_expression(frame.expression))
      return cannot_carry(flavour, at + "FAP 2 is one value there (expression_select1 at intensity 63); this "
                                        "expression record needs the safe, xface or greta-cpp flavour, or FAP 2 masked "
                                        "off");
  }
  return std::nullopt;
}

}  // namespace

std::string_view fap_flavour_name(FapFlavour flavour) {
  for (const auto& [f, name] : kFlavourNames)
    if (f == flavour) return name;
  return "safe";
}

std::optional<FapFlavour> fap_flavour_named(std::string_view name) {
  for (const auto& [f, known] : kFlavourNames)
    if (known == name) return f;
  return std::nullopt;
}

std::string fap_flavour_names() {
  std::string names;
  for (const auto& [f, name] : kFlavourNames) names += (names.empty() ? "" : "|") + std::string(name);
  return names;
}

std::string safe_header_name(std::string_view name) {
  // The base name only: readers choke on long paths (the reference coder above 127 characters).
  const auto slash = name.find_last_of("/\\");
  if (slash != std::string_view::npos) name.remove_prefix(slash + 1);
  std::string out;
  for (char c : name) {
    const bool blank = c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
    out += blank ? '_' : c;
  }
  if (out.size() > 100) out.resize(100);
  return out.empty() ? "fapc" : out;
}

FapTextWriter::FapTextWriter(const std::string& name, int fps, std::size_t frames, std::int64_t first_number,
                             std::int64_t last_number, const FapWriteOptions& options)
    : options_(options), fps_(fps), first_(first_number) {
  renumber_ = options.renumber || options.flavour != FapFlavour::safe;
  count_ = static_cast<long long>(frames);
  if (renumber_ && frames > 0) count_ = last_number - first_number + 1;
  name_ = safe_header_name(name);
}

FapTextWriter::~FapTextWriter() = default;

Status FapTextWriter::begin(std::string& out) {
  if (auto problem = check_rate(fps_, options_.flavour, layout_of(options_.flavour))) return *problem;
  if (layout_of(options_.flavour).header)
    out += "2.1 " + name_ + " " + std::to_string(fps_) + " " + std::to_string(count_) + "\n";
  else if (layout_of(options_.flavour).millisecond_numbers)
    out += "0\n";
  return ok_status();
}

Status FapTextWriter::add(const FapFrame& frame, std::string& out) {
  if (auto problem = check_frame(frame, options_.flavour, layout_of(options_.flavour))) return *problem;
  if (pending_) write_pending(frame.number, out);
  pending_ = frame;
  return ok_status();
}

void FapTextWriter::finish(std::string& out) {
  if (pending_) write_pending(pending_->number + 1, out);
  pending_.reset();
}

void FapTextWriter::write_pending(std::int64_t next_number, std::string& out) {
  const FapFrame& frame = *pending_;
  if (!renumber_) {
    append_frame(out, frame, frame.number, layout_of(options_.flavour), options_);
    return;
  }
  // Gaps are filled by repeating the frame before them: players read frame k at row k.
  const long long ms_per_frame = layout_of(options_.flavour).millisecond_numbers ? 1000 / fps_ : 0;
  for (long long n = frame.number - first_; n < next_number - first_; ++n)
    append_frame(out, frame, layout_of(options_.flavour).millisecond_numbers ? (n + 1) * ms_per_frame : n,
                 layout_of(options_.flavour), options_);
}

namespace {

Result<std::string> write_layout(const FapSequence& sequence, const FapWriteOptions& options) {
  const auto& frames = sequence.frames;
  FapTextWriter writer(sequence.name, sequence.fps, frames.size(), frames.empty() ? 0 : frames.front().number,
                       frames.empty() ? 0 : frames.back().number, options);
  std::string out;
  out.reserve(frames.size() * 400 + 128);
  // Every frame is checked before any text is made: the first frame the flavour cannot carry.
  if (auto status = writer.begin(out); !status) return status.error();
  for (const FapFrame& frame : frames)
    if (auto status = writer.add(frame, out); !status) return status.error();
  writer.finish(out);
  return out;
}

}  // namespace

Result<std::string> write_fap_flavour(const FapSequence& sequence, const FapWriteOptions& options) {
  return write_layout(sequence, options);
}

std::string write_fap_text(const FapSequence& sequence, const FapWriteOptions& options) {
  FapWriteOptions safe = options;
  safe.flavour = FapFlavour::safe;
  return *write_layout(sequence, safe);
}

}  // namespace fapc

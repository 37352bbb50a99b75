// The .fap writer: the safe form every known reader accepts (docs/fap-files.md section 5), and
// the flavour of each player family (docs/fap-files.md, "Flavours").
#include <array>
#include <string>

#include "fapc/codec/fap_file.hpp"

namespace fapc {

namespace {

// What distinguishes the flavours, from each family's reader (docs/fap-files.md section 3).
struct Layout {
  bool header;          // `2.1 <name> <fps> <n>`; SEMAINE messages have none
  int mask_tokens;      // 68, or 69 with a final 0 (Greta's Java writer and reader)
  bool single_fap12;    // FAP 1 and FAP 2 as one value each instead of 4 and 6 fields
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

void append_int(std::string& out, long long v) {
  out += std::to_string(v);
  out += ' ';
}

void end_line(std::string& out, bool trailing_space) {
  if (!trailing_space && !out.empty() && out.back() == ' ') out.pop_back();
  out += '\n';
}

void append_frame(std::string& out, const FapFrame& frame, long long number, const Layout& layout,
                  const FapWriteOptions& options) {
  for (std::size_t i = 0; i < kFapCount; ++i) append_int(out, frame.mask.test(i) ? 1 : 0);
  if (layout.mask_tokens == kFapCount + 1) append_int(out, 0);
  end_line(out, options.trailing_space);
  append_int(out, number);
  if (frame.has(1)) {
    const VisemeFields& v = frame.viseme;
    if (layout.single_fap12) append_int(out, v.select1);
    else for (int x : {v.select1, v.select2, v.blend, v.def}) append_int(out, x);
  }
  if (frame.has(2)) {
    const ExpressionFields& e = frame.expression;
    if (layout.single_fap12) append_int(out, e.select1);
    else for (int x : {e.select1, e.intensity1, e.select2, e.intensity2, e.init_face, e.def}) append_int(out, x);
  }
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (frame.has(fap)) append_int(out, frame.value(fap));
  end_line(out, options.trailing_space);
}

Diagnostic cannot_carry(FapFlavour flavour, const std::string& what) {
  return make_error(ErrorKind::unsupported, Location{},
                    "the " + std::string(fap_flavour_name(flavour)) + " .fap flavour cannot carry " + what);
}

std::optional<Diagnostic> check_carried(const FapSequence& sequence, FapFlavour flavour, const Layout& layout) {
  if (layout.millisecond_numbers && (sequence.fps <= 0 || 1000 % sequence.fps != 0))
    return cannot_carry(flavour, std::to_string(sequence.fps) +
                                     " frames per second: it numbers frames in whole milliseconds (25 fps, Greta's "
                                     "rate, is 40 ms a frame)");
  if (!layout.single_fap12) return std::nullopt;
  for (const FapFrame& frame : sequence.frames) {
    const std::string at = "frame " + std::to_string(frame.number) + ": ";
    if (frame.has(1) && !single_viseme(frame.viseme))
      return cannot_carry(flavour, at + "FAP 1 is one value there (viseme_select1 shown alone, blend 63); this "
                                        "viseme record needs the safe, xface or greta-cpp flavour, or FAP 1 masked off");
    if (frame.has(2) && !single_expression(frame.expression))
      return cannot_carry(flavour, at + "FAP 2 is one value there (expression_select1 at intensity 63); this "
                                        "expression record needs the safe, xface or greta-cpp flavour, or FAP 2 masked "
                                        "off");
  }
  return std::nullopt;
}

std::string write_layout(const FapSequence& sequence, const Layout& layout, const FapWriteOptions& options) {
  const auto& frames = sequence.frames;
  const bool renumber = options.renumber || options.flavour != FapFlavour::safe;
  // With renumbering, absent frames (gaps in the numbers) are filled by repeating the frame
  // before them, so the written frames 0..n-1 keep the sequence's timing.
  long long count = static_cast<long long>(frames.size());
  if (renumber && !frames.empty()) count = frames.back().number - frames.front().number + 1;
  std::string out;
  out.reserve(frames.size() * 400 + 128);
  // SEMAINE's messages open with a time 40 ms (one frame) before the first frame's stamp; the
  // stamps then start one frame in, as in its 2008 files (280 -> 320).
  const long long ms_per_frame = layout.millisecond_numbers ? 1000 / sequence.fps : 0;
  if (layout.header)
    out += "2.1 " + safe_header_name(sequence.name) + " " + std::to_string(sequence.fps) + " " + std::to_string(count) + "\n";
  else if (layout.millisecond_numbers)
    out += "0\n";
  const auto number_of = [&](long long n) { return layout.millisecond_numbers ? (n + 1) * ms_per_frame : n; };
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (!renumber) {
      append_frame(out, frames[i], frames[i].number, layout, options);
      continue;
    }
    const long long first = frames[i].number - frames.front().number;
    const long long until = i + 1 < frames.size() ? frames[i + 1].number - frames.front().number : first + 1;
    for (long long n = first; n < until; ++n) append_frame(out, frames[i], number_of(n), layout, options);
  }
  return out;
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

Result<std::string> write_fap_flavour(const FapSequence& sequence, const FapWriteOptions& options) {
  const Layout layout = layout_of(options.flavour);
  if (auto problem = check_carried(sequence, options.flavour, layout)) return *problem;
  return write_layout(sequence, layout, options);
}

std::string write_fap_text(const FapSequence& sequence, const FapWriteOptions& options) {
  FapWriteOptions safe = options;
  safe.flavour = FapFlavour::safe;
  return write_layout(sequence, layout_of(FapFlavour::safe), safe);
}

}  // namespace fapc

// A solved block to clips (docs/bml.md, "What is drawn"): speech to visemes and voice, head
// lexemes to head rotations, gaze to the eyes (and the head, by influence), faces to their
// action units' FAPs.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "bml/bml_model.hpp"
#include "bml/face_lowering.hpp"
#include "bml/lexicon_behaviours.hpp"
#include "fapc/bml/codes.hpp"
#include "fapc/transcoder/audio_mix.hpp"

namespace fapc::bml {
namespace {

// FAP angle units are 1e-5 rad.
constexpr double kAngleUnitsPerDegree = 1e5 * std::numbers::pi / 180.0;

Clip keyed_clip(const std::string& target, double origin, const std::array<double, kStandardPoints>& t,
                std::vector<KeyPoint> keys, const Location& where, Fill fill) {
  Clip clip;
  clip.target = target;
  clip.begin = origin + t[kStart];
  clip.end = origin + t[kEnd];
  clip.curve.keys = std::move(keys);
  clip.blend = BlendMode::add;
  clip.fill = fill;
  clip.source = where;
  return clip;
}

// A nod or shake: `repetition` swings of the head out to `amplitude` and back, the first reaching
// its extreme at the stroke (BML's stroke: the most effortful moment), the last back by strokeEnd.
std::vector<KeyPoint> swings(const std::array<double, kStandardPoints>& t, double amplitude, int repetition) {
  const double s = t[kStart];
  std::vector<KeyPoint> keys{{0, 0, Interpolation::sin}, {t[kStroke] - s, amplitude, Interpolation::sin}};
  const double half = (t[kStrokeEnd] - t[kStroke]) / (2 * repetition - 1);
  for (int i = 1; i < 2 * repetition; ++i)
    keys.push_back({t[kStroke] - s + half * i, i % 2 == 0 ? amplitude : 0.0, Interpolation::sin});
  keys.push_back({t[kEnd] - s, 0, Interpolation::linear});
  return keys;
}

// Yaw and pitch (degrees; yaw to the character's left, pitch down, as FAPs 23-26 and 48-49 turn)
// of an offsetDirection and offsetAngle.
std::pair<double, double> direction_degrees(const Behaviour& b) {
  const double a = b.offset_angle;
  const std::string& d = b.offset_direction;
  double yaw = 0;
  double pitch = 0;
  if (d.find("RIGHT") != std::string::npos) yaw = -a;
  if (d.find("LEFT") != std::string::npos) yaw = a;
  if (d.find("UP") != std::string::npos) pitch = -a;
  if (d.find("DOWN") != std::string::npos) pitch = a;
  if (d.size() > 4 && (d.starts_with("UP") || d.starts_with("DOWN"))) {  // diagonals: the angle along both
    yaw *= std::numbers::sqrt2 / 2;
    pitch *= std::numbers::sqrt2 / 2;
  }
  return {yaw, pitch};
}

void lower_head(const Behaviour& b, const std::array<double, kStandardPoints>& t, double origin, Timeline& out,
                Diagnostics& warnings) {
  // Amplitudes at amount 1: a conversational nod dips some 10 degrees, a shake turns 12, a tilt 10.
  const std::string& l = b.lexeme;
  const double amount = b.amount;
  auto add = [&](const char* target, std::vector<KeyPoint> keys) {
    out.clips.push_back(keyed_clip(target, origin, t, std::move(keys), b.where, Fill::remove));
  };
  if (l == "NOD") {
    add("head_pitch", swings(t, 10 * amount * kAngleUnitsPerDegree, b.repetition));
  } else if (l == "SHAKE") {
    // A shake swings to one side and the other: half the swings each way.
    std::vector<KeyPoint> keys = swings(t, 12 * amount * kAngleUnitsPerDegree, b.repetition);
    bool left = true;
    for (KeyPoint& k : keys)
      if (k.value != 0) {
        if (!left) k.value = -k.value;
        left = !left;
      }
    add("head_yaw", std::move(keys));
  } else if (l == "TILT" || l == "TILT_LEFT" || l == "TILT_RIGHT") {
    // head_roll turns to the right for positive values; TILT alone leans right.
    const double sign = l == "TILT_LEFT" ? -1 : 1;
    add("head_roll", envelope(t, sign * 10 * amount * kAngleUnitsPerDegree, false));
  } else {
    warnings.push_back(make_warning(
        codes::bml::unknown_head_lexeme, b.where,
        "head lexeme '" + l + "' is not one fapc draws (NOD, SHAKE, TILT, TILT_LEFT, TILT_RIGHT): its timing is kept"));
  }
}

void lower_direction(const Behaviour& b, const std::array<double, kStandardPoints>& t, double origin, Timeline& out) {
  const auto [yaw, pitch] = direction_degrees(b);
  // The head takes the larger part of a turn when the gaze's influence reaches it (HEAD, NECK,
  // SHOULDER, WAIST, WHOLE): 60 %, leaving the eyes the rest, as people turn (docs/bml.md).
  const bool head = b.kind == BehaviourKind::head_direction || (b.influence != "EYES" && !b.influence.empty());
  const double head_share = b.kind == BehaviourKind::head_direction ? 1.0 : head ? 0.6 : 0.0;
  const Fill fill = b.shift ? Fill::freeze : Fill::remove;
  auto add = [&](const char* target, double degrees) {
    if (degrees == 0) return;
    out.clips.push_back(
        keyed_clip(target, origin, t, envelope(t, degrees * kAngleUnitsPerDegree, b.shift), b.where, fill));
  };
  add("head_yaw", yaw * head_share);
  add("head_pitch", pitch * head_share);
  if (b.kind == BehaviourKind::gaze) {
    const double eyes = 1 - head_share;
    for (const char* target : {"yaw_l_eyeball", "yaw_r_eyeball"}) add(target, yaw * eyes);
    for (const char* target : {"pitch_l_eyeball", "pitch_r_eyeball"}) add(target, pitch * eyes);
  }
}

void lower_speech(const Behaviour& b, const std::array<double, kStandardPoints>& t, double origin,
                  const Coarticulation& rule, Timeline& out) {
  const SpokenText& spoken = *b.speech;
  const double begin = origin + t[kStart];
  for (Clip clip : coarticulated_viseme_clips(spoken.visemes, 1.0, rule, b.where)) {
    clip.begin += begin;
    clip.end += begin;
    out.clips.push_back(std::move(clip));
  }
  if (!spoken.audio.samples.empty()) {
    AudioClip voice = spoken.audio;
    voice.begin = begin;
    out.audio.push_back(std::move(voice));
  }
}

// The block's lips rows (SmartBody's recorded visemes) as one viseme track: each row held from
// its start to its end at its articulation, cross-faded with its neighbours by the coarticulation
// rule of synthesised speech, as one utterance's visemes are (rows are lowered together so that
// each fade is shared by the two rows it joins). Touching rows of one viseme and articulation are
// one held shape; a row that overlaps the one before it starts where that one ends.
void lower_lips(const Block& block, const Solution& solution, double origin, const Coarticulation& rule,
                Timeline& out) {
  struct Row {
    VisemeSpan span;
    Location where;
  };
  std::vector<Row> rows;
  for (std::size_t i = 0; i < block.behaviours.size(); ++i) {
    const Behaviour& b = block.behaviours[i];
    const auto& t = solution.points[i];
    if (b.kind == BehaviourKind::lips && t[kEnd] > t[kStart])
      rows.push_back({VisemeSpan{b.viseme, origin + t[kStart], origin + t[kEnd], b.amount}, b.where});
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.span.begin < b.span.begin; });
  std::vector<VisemeSpan> spans;
  std::vector<Location> sources;
  double previous_end = 0;
  for (Row& row : rows) {
    VisemeSpan s = row.span;
    s.begin = std::max(s.begin, previous_end);
    if (s.end <= s.begin) continue;
    previous_end = s.end;
    if (s.viseme <= 0 || s.weight <= 0) continue;  // rest: the mouth at its neutral
    if (!spans.empty() && spans.back().viseme == s.viseme && spans.back().weight == s.weight &&
        std::abs(spans.back().end - s.begin) < 1e-9) {
      spans.back().end = s.end;
      continue;
    }
    spans.push_back(s);
    sources.push_back(row.where);
  }
  if (spans.empty()) return;
  std::vector<Clip> clips = coarticulated_viseme_clips(spans, 1.0, rule, sources.front());
  // One clip per row, unless a widened short row swallowed a neighbour: then the first row names them.
  if (clips.size() == sources.size())
    for (std::size_t i = 0; i < clips.size(); ++i) clips[i].source = sources[i];
  for (Clip& clip : clips) out.clips.push_back(std::move(clip));
}

// About how many clips a behaviour makes (exact for faces, which are most of a large document):
// the timeline is reserved once rather than copied as it grows (at 10^5 behaviours, each copy
// was tens of megabytes of fresh pages).
std::size_t clip_estimate(const Behaviour& b) {
  switch (b.kind) {
    case BehaviourKind::face_lexeme:
    case BehaviourKind::face_facs:
      return face_clip_count(b);
    case BehaviourKind::head:
      return 1;
    case BehaviourKind::gaze:
    case BehaviourKind::head_direction:
      return 2;
    case BehaviourKind::lexicon_rows:
      return b.rows.size();
    case BehaviourKind::speech:
      return b.speech ? b.speech->visemes.size() : 0;
    case BehaviourKind::lips:
    case BehaviourKind::wait:
    case BehaviourKind::not_drawn:
      return 0;
  }
  return 0;
}

}  // namespace

void lower_behaviour(const Behaviour& b, const std::array<double, kStandardPoints>& t, double origin,
                     const Coarticulation& rule, Timeline& out, Diagnostics& warnings) {
  const bool drawn =
      b.kind != BehaviourKind::wait && b.kind != BehaviourKind::not_drawn && b.kind != BehaviourKind::speech;
  if (drawn && !(t[kEnd] > t[kStart])) {
    // start = end is a consistent schedule (two sync points joined) but moves nothing: said, not
    // drawn, so that every clip of the timeline lasts some time.
    warnings.push_back(
        make_warning(codes::bml::no_duration, b.where,
                     "<" + b.element + " id=\"" + b.id + "\"> starts and ends at the same moment: it moves nothing"));
    return;
  }
  switch (b.kind) {
    case BehaviourKind::face_lexeme:
    case BehaviourKind::face_facs:
      lower_face(b, t, origin, out, warnings);
      break;
    case BehaviourKind::head:
      lower_head(b, t, origin, out, warnings);
      break;
    case BehaviourKind::gaze:
    case BehaviourKind::head_direction:
      lower_direction(b, t, origin, out);
      break;
    case BehaviourKind::speech:
      lower_speech(b, t, origin, rule, out);
      break;
    case BehaviourKind::lips:  // with the block's other rows, in lower_block
      break;
    case BehaviourKind::wait:
    case BehaviourKind::not_drawn:
      break;
    case BehaviourKind::lexicon_rows:
      // Each row is its own behaviour over this one's span, as an intention's rows are.
      for (std::size_t i = 0; i < b.rows.size(); ++i) {
        Behaviour part = behaviour_of(*b.rows[i], b.amount * b.row_shares[i], b.where);
        if (part.kind == BehaviourKind::not_drawn) continue;
        part.id = b.id;
        part.element = b.element;
        part.repetition = std::max(1, static_cast<int>(std::lround(part.repetition * b.repetition_scale)));
        lower_behaviour(part, points_of(*b.rows[i], t[kStart], t[kEnd], b.onset_scale), origin, rule, out, warnings);
      }
      break;
  }
}

void lower_block(const Block& block, const Solution& solution, double origin, const Coarticulation& rule, Timeline& out,
                 Diagnostics& warnings) {
  std::size_t clips = out.clips.size();
  for (const Behaviour& b : block.behaviours) clips += clip_estimate(b);
  out.clips.reserve(clips);
  for (std::size_t i = 0; i < block.behaviours.size(); ++i)
    lower_behaviour(block.behaviours[i], solution.points[i], origin, rule, out, warnings);
  lower_lips(block, solution, origin, rule, out);
}

}  // namespace fapc::bml

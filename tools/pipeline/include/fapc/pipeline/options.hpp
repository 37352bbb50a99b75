// The options every conversion takes: what the command line's --fps, --profile, --quant... set.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/limits.hpp"

namespace fapc::pipeline {

// The picture outputs (.png, .webm, .html): --size, --frame-rate, --frame, --time, --sheet.
struct PictureSettings {
  int width = 640;
  int height = 480;
  int frame_rate = 0;                 // 0: the input's own frame rate
  std::optional<std::int64_t> frame;  // .png: this frame of the input's grid
  std::optional<double> time;         // .png: the frame at this time
  std::optional<int> sheet;           // .png: a contact sheet of N frames
  bool points = false;                // .png: the feature points marked and numbered
  std::string view = "2d";            // .html: 2d | 3d | both (the 3D head, docs/render.md)
  std::string morphs = "faps";        // .glb/.gltf: the targets named faps | arkit
};

// How far a long job is: `done` of `total` steps of `stage` ("writing x.webm"). Called on the
// thread doing the work; the library never prints, the program decides what to show.
using ProgressFn = std::function<void(std::string_view stage, std::int64_t done, std::int64_t total)>;

struct ConvertOptions {
  int fps = 25;
  // --from: the kind of the top input whatever its name (standard input has none); empty: from the
  // extension. Inputs it includes never inherit it.
  std::string input_kind;
  ProgressFn progress;                        // empty: nobody is told
  PictureSettings picture;                    // the face outputs
  std::optional<std::string> profile;         // a profile file; empty: the default profile
  std::optional<std::string> lexicon;         // a behaviour lexicon (--lexicon); empty: fapc's own
  std::optional<double> duration;             // the end of timelines that give none
  std::map<std::string, std::string> events;  // FML events, NAME -> VALUE
  // FML talk text (docs/speech.md): the speaking rate in words per minute (--speech-rate, 80 to
  // 450; the letter table without an engine speaks rate * 12 / 175 visemes per second), the voice
  // (--voice LANGUAGE[+VARIANT] or +VARIANT) where the document names none, and whether to use the
  // speech engine at all (false: the letter table, as in a build without one).
  double words_per_minute = 175;
  std::string voice;
  bool speech_engine = true;
  int quant = 1;                              // fap_quant for .fba/.mp4 outputs
  int intra_period = 0;                       // 0: the encoder decides
  std::string ranges = "fit";                 // fit | max
  std::string masks = "fit";                  // fit | keep
  FapFlavour fap_flavour = FapFlavour::safe;  // the .fap layout of a player family
  bool strict = false;                        // warnings are errors; nothing is written
  bool verify = false;                        // encoded streams are decoded and checked
  Limits limits;                              // --max-frames, --max-runs, --max-decompressed-bytes, --max-expansion
  // Which files includes may read (docs/security.md): load() adds the top input's folder.
  IncludePolicy includes;
  // What a load does beyond the frames (see Loaded):
  bool facts = false;  // fill Loaded::facts (what `fapc info` shows of the format)
  bool render = true;  // false: timeline inputs stop at the timeline (no frames, no curves)
  // With render false: the caller renders the timeline itself at fps (the streamed compile), so
  // the frame limit still applies and front ends check it as soon as they know the end.
  bool renders_later = false;
  // false: timeline inputs leave Loaded::curves empty. convert() sets it from its outputs
  // (OutputFormat::uses_curves): curves cost as much as the frames and most outputs never read them.
  bool curves = true;
  // false: timeline inputs render their frames without keeping them, for their warnings, errors
  // and summary (Loaded::frames_not_kept). convert() sets it from its outputs
  // (OutputFormat::uses_frames): the curves JSON and the plots of a script read its curves.
  bool frames = true;
  // Asked before a script's frames are rendered, with their count, their rate and the place that
  // ends the animation: convert() sets it from its outputs (OutputFormat::check_length).
  std::function<Status(std::int64_t frames, int fps, const Location& ends)> check_length;
  // The options the command line was given, by name without "--": convert() warns
  // (format.option_not_read) of those some input kind reads that neither the input's row nor an
  // output's names (docs/cli.md, "Options a kind does not read"). Empty: nothing is said.
  std::vector<std::string> given;
};

}  // namespace fapc::pipeline

#include "fapc/options.hpp"

#include <cstdio>
#include <sstream>

#include "fapc/codec/did_you_mean.hpp"

namespace fapc::cli {

ConvertOptions convert_options(Args& args) {
  ConvertOptions options;
  options.fps = args.integer("fps", 25, 1, 1000);
  options.quant = args.integer("quant", 1, 0, 31);
  options.intra_period = args.integer("intra-period", 0, 0, 1 << 20);
  options.profile = args.value("profile");
  options.lexicon = args.value("lexicon");
  options.duration = args.decimal("duration", 0, 1e7);
  if (const auto rate = args.decimal("speech-rate", 80, 450)) options.words_per_minute = *rate;  // words per minute
  if (const auto voice = args.value("voice")) options.voice = *voice;
  // The resource limits (docs/security.md): only ever raised or lowered on purpose.
  options.limits.max_frames = args.integer("max-frames", static_cast<int>(options.limits.max_frames), 1, 1 << 30);
  options.limits.max_runs = args.integer("max-runs", static_cast<int>(options.limits.max_runs), 1, 1 << 30);
  if (const auto bytes = args.decimal("max-decompressed-bytes", 1, 1e15))
    options.limits.max_decompressed_bytes = static_cast<std::int64_t>(*bytes);
  if (const auto factor = args.decimal("max-expansion", 1, 1e9)) options.limits.max_expansion = *factor;
  if (const auto samples = args.decimal("max-audio-samples", 1, 1e15))
    options.limits.max_audio_samples = static_cast<std::int64_t>(*samples);
  if (const auto bytes = args.decimal("max-speech-text", 1, 1e12))
    options.limits.max_speech_text_bytes = static_cast<std::int64_t>(*bytes);
  if (const auto seconds = args.decimal("max-speech-seconds", 1, 1e9)) options.limits.max_speech_seconds = *seconds;
  // Pictures (docs/security.md): pixels per picture, per contact sheet, per video in all.
  const auto pixels = [&args](const char* name, std::int64_t& into) {
    if (const auto value = args.decimal(name, 1, 1e15)) into = static_cast<std::int64_t>(*value);
  };
  pixels("max-frame-pixels", options.limits.max_frame_pixels);
  pixels("max-sheet-pixels", options.limits.max_sheet_pixels);
  pixels("max-video-pixels", options.limits.max_video_pixels);
  options.strict = args.flag("strict");
  options.verify = args.flag("verify");
  // Two-way choices: the option's value must be one of the two words.
  const auto choose = [&args](const char* name, const char* first, const char* second, std::string& into) {
    const auto value = args.value(name);
    if (!value) return true;
    if (*value != first && *value != second) {
      args.fail(codes::cli::bad_option_value,
                std::string("--") + name + " takes " + first + " or " + second + ", not '" + *value + "'");
      return false;
    }
    into = *value;
    return true;
  };
  if (!choose("ranges", "fit", "max", options.ranges) || !choose("masks", "fit", "keep", options.masks)) return options;
  if (!choose("morphs", "faps", "arkit", options.picture.morphs)) return options;
  if (const auto size = args.value("size")) {
    int w = 0, h = 0;
    char x = 0, rest = 0;
    if (std::sscanf(size->c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || x != 'x' || w < 16 || h < 16 || w > 7680 ||
        h > 7680) {
      args.fail(codes::cli::bad_option_value, "--size takes WIDTHxHEIGHT, each 16 to 7680 pixels, not '" + *size + "'");
      return options;
    }
    options.picture.width = w;
    options.picture.height = h;
  }
  options.picture.frame_rate = args.integer("frame-rate", 0, 1, 120);
  if (args.value("frame")) options.picture.frame = args.integer("frame", 0, 0, 1 << 30);
  options.picture.time = args.decimal("time", 0, 1e7);
  options.picture.points = args.flag("points");
  if (const auto view = args.value("view")) {
    if (*view != "2d" && *view != "3d" && *view != "both") {
      args.fail(codes::cli::bad_option_value, "--view takes 2d, 3d or both, not '" + *view + "'");
      return options;
    }
    options.picture.view = *view;
  }
  if (args.value("sheet")) options.picture.sheet = args.integer("sheet", 12, 1, 400);
  // Folders whose files includes may read besides the input's own (docs/security.md).
  for (const std::string& folder : args.values("allow-include")) options.includes.allowed_folders.push_back(folder);
  if (const auto flavour = args.value("fap-flavour")) {
    const auto known = fap_flavour_named(*flavour);
    if (!known) {
      std::vector<std::string> names;
      std::istringstream all(fap_flavour_names());
      for (std::string name; std::getline(all, name, '|');) names.push_back(name);
      args.fail(codes::cli::bad_option_value, "--fap-flavour takes " + fap_flavour_names() + ", not '" + *flavour +
                                                  "'" + did_you_mean(*flavour, names));
    }
    options.fap_flavour = known.value_or(FapFlavour::safe);
  }
  for (const std::string& event : args.values("event")) {
    const auto eq = event.find('=');
    if (eq == std::string::npos || eq == 0) {
      args.fail(codes::cli::bad_option_value, "--event takes NAME=VALUE, not '" + event + "'");
      return options;
    }
    options.events[event.substr(0, eq)] = event.substr(eq + 1);
  }
  return options;
}

}  // namespace fapc::cli

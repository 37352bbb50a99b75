#include "fapc/options.hpp"

#include <cstdio>
#include <sstream>

#include "fapc/codec/did_you_mean.hpp"

namespace fapc::cli {

ConvertOptions convert_options(Args& args) {
  ConvertOptions options;
  // Each number is read within the range its declaration gives (cli_spec.cpp); absent, the
  // library's own default stays.
  options.fps = args.integer("fps", options.fps);
  options.quant = args.integer("quant", options.quant);
  options.intra_period = args.integer("intra-period", options.intra_period);
  options.profile = args.value("profile");
  options.lexicon = args.value("lexicon");
  options.duration = args.decimal("duration");
  if (const auto rate = args.decimal("speech-rate")) options.words_per_minute = *rate;  // words per minute
  if (const auto voice = args.value("voice")) options.voice = *voice;
  // The resource limits (docs/security.md): only ever raised or lowered on purpose.
  options.limits.max_frames = args.integer("max-frames", static_cast<int>(options.limits.max_frames));
  options.limits.max_runs = args.integer("max-runs", static_cast<int>(options.limits.max_runs));
  const auto count = [&args](const char* name, std::int64_t& into) {
    if (const auto value = args.decimal(name)) into = static_cast<std::int64_t>(*value);
  };
  count("max-decompressed-bytes", options.limits.max_decompressed_bytes);
  if (const auto factor = args.decimal("max-expansion")) options.limits.max_expansion = *factor;
  count("max-audio-samples", options.limits.max_audio_samples);
  count("max-speech-text", options.limits.max_speech_text_bytes);
  if (const auto seconds = args.decimal("max-speech-seconds")) options.limits.max_speech_seconds = *seconds;
  // Pictures (docs/security.md): pixels per picture, per contact sheet, per video in all.
  count("max-frame-pixels", options.limits.max_frame_pixels);
  count("max-sheet-pixels", options.limits.max_sheet_pixels);
  count("max-video-pixels", options.limits.max_video_pixels);
  // For the warning of an option the input's kind does not read (docs/cli.md).
  options.given = args.given();
  options.strict = args.flag("strict");
  options.verify = args.flag("verify");
  // Choices: the option's value must be one of its declared words.
  const auto choose = [&args](const char* name, std::string& into) {
    if (const auto word = args.word(name)) into = *word;
    return args.ok();
  };
  if (!choose("ranges", options.ranges) || !choose("masks", options.masks)) return options;
  if (!choose("morphs", options.picture.morphs)) return options;
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
  options.picture.frame_rate = args.integer("frame-rate", options.picture.frame_rate);
  if (args.value("frame")) options.picture.frame = args.integer("frame", 0);
  options.picture.time = args.decimal("time");
  options.picture.points = args.flag("points");
  if (!choose("view", options.picture.view)) return options;
  if (args.value("sheet")) options.picture.sheet = args.integer("sheet", 0);
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

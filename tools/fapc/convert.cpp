#include "fapc/convert.hpp"

#include <cstdio>
#include <iostream>

#include "fapc/codec/file_io.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

ConvertOptions convert_options(Args& args) {
  ConvertOptions options;
  options.fps = args.integer("fps", 25, 1, 1000);
  options.quant = args.integer("quant", 1, 0, 31);
  options.intra_period = args.integer("intra-period", 0, 0, 1 << 20);
  options.profile = args.value("profile");
  options.duration = args.decimal("duration", 0, 1e7);
  if (const auto rate = args.decimal("speech-rate", 0.1, 100)) options.visemes_per_second = *rate;
  options.strict = args.flag("strict");
  options.verify = args.flag("verify");
  // Two-way choices: the option's value must be one of the two words.
  const auto choose = [&args](const char* name, const char* first, const char* second, std::string& into) {
    const auto value = args.value(name);
    if (!value) return true;
    if (*value != first && *value != second) {
      args.fail(std::string("--") + name + " takes " + first + " or " + second + ", not '" + *value + "'");
      return false;
    }
    into = *value;
    return true;
  };
  if (!choose("ranges", "fit", "max", options.ranges) || !choose("masks", "fit", "keep", options.masks)) return options;
  if (const auto size = args.value("size")) {
    int w = 0, h = 0;
    char x = 0, rest = 0;
    if (std::sscanf(size->c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || x != 'x' || w < 16 ||
        h < 16 || w > 7680 || h > 7680) {
      args.fail("--size takes WIDTHxHEIGHT, each 16 to 7680 pixels, not '" + *size + "'");
      return options;
    }
    options.picture.width = w;
    options.picture.height = h;
  }
  options.picture.frame_rate = args.integer("frame-rate", 0, 1, 120);
  if (args.value("frame")) options.picture.frame = args.integer("frame", 0, 0, 1 << 30);
  options.picture.time = args.decimal("time", 0, 1e7);
  options.picture.points = args.flag("points");
  if (args.value("sheet")) options.picture.sheet = args.integer("sheet", 12, 1, 400);
  // Folders whose files includes may read besides the input's own (docs/security.md).
  for (const std::string& folder : args.values("allow-include")) options.includes.allowed_folders.push_back(folder);
  if (const auto flavour = args.value("fap-flavour")) {
    const auto known = fap_flavour_named(*flavour);
    if (!known) args.fail("--fap-flavour takes " + fap_flavour_names() + ", not '" + *flavour + "'");
    options.fap_flavour = known.value_or(FapFlavour::safe);
  }
  for (const std::string& event : args.values("event")) {
    const auto eq = event.find('=');
    if (eq == std::string::npos || eq == 0) {
      args.fail("--event takes NAME=VALUE, not '" + event + "'");
      return options;
    }
    options.events[event.substr(0, eq)] = event.substr(eq + 1);
  }
  return options;
}

namespace {

const OutputFormat* writer_for(const std::string& output, const std::string& to_kind) {
  const OutputFormat* writer =
      to_kind.empty() ? output_format_for(output) : output_format_named(to_kind);
  if (!writer) {
    report(make_error(Location{output, 0, 0, -1},
                      "unknown output kind (expected .fap, .fap.gz, .fba, .mp4, .xmt, .json, .svg, .png, .webm or .html)"));
  }
  return writer;
}

int write_with(const OutputFormat& writer, const Loaded& loaded, const std::string& output,
               const ConvertOptions& options) {
  auto bytes = writer.write(loaded, output, options);
  if (!bytes) {
    report(bytes.error());
    return bytes.error().message.rfind("verification", 0) == 0 ? kExitVerifyFailed : kExitBadInput;
  }
  if (output == "-") {
    std::cout << *bytes << std::flush;
  } else if (auto written = write_file_atomic(output, *bytes); !written) {
    report(written.error());
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace

int write_output(const Loaded& loaded, const std::string& output, const ConvertOptions& options,
                 const std::string& to_kind) {
  const OutputFormat* writer = writer_for(output, to_kind);
  return writer ? write_with(*writer, loaded, output, options) : kExitBadInput;
}

ConvertOutcome convert(const std::string& input, const std::string& output,
                       const ConvertOptions& options, const std::string& to_kind) {
  ConvertOutcome outcome;
  // The output kind is checked first: a typo in -o should not cost a long compile.
  const OutputFormat* writer = writer_for(output, to_kind);
  if (!writer) {
    outcome.exit_status = kExitBadInput;
    return outcome;
  }
  auto loaded = load_input(input, options);
  if (!loaded) {
    report(loaded.error());
    outcome.exit_status = kExitBadInput;
    return outcome;
  }
  report_all(loaded->warnings);
  if (options.strict && !loaded->warnings.empty()) {
    std::cerr << input << ": error: " << loaded->warnings.size()
              << " warning(s) treated as errors (--strict); nothing written\n";
    outcome.exit_status = kExitBadInput;
    return outcome;
  }
  outcome.exit_status = write_with(*writer, *loaded, output, options);
  if (outcome.exit_status == kExitOk) outcome.loaded = std::move(*loaded);
  return outcome;
}

}  // namespace fapc::cli

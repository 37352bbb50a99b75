// Helpers of the intention tests: documents written to a private temporary folder and loaded by
// the real pipeline, and FAP values read off its frames.
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "fapc/pipeline/registry.hpp"
#include "support/test_support.hpp"

namespace fapc::test {

inline std::string write_temp(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = test::scratch_folder("intent");
  const std::filesystem::path path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

inline Result<pipeline::Loaded> load_at_25(const std::string& path, std::optional<std::string> lexicon = std::nullopt) {
  pipeline::ConvertOptions options;
  options.fps = 25;
  options.lexicon = std::move(lexicon);
  return pipeline::load(path, options);
}

// FAP `fap` in the frame at `seconds` (0 when the frame does not set it or does not exist).
inline double fap_at(const FapSequence& frames, int fap, double seconds) {
  const auto index = static_cast<std::size_t>(seconds * frames.fps + 0.5);
  if (index >= frames.frames.size()) return 0;
  const FapFrame& f = frames.frames[index];
  return f.has(fap) ? f.value(fap) : 0;
}

}  // namespace fapc::test

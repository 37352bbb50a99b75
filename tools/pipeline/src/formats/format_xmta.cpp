// XMT-A outputs (docs/mp4-and-xmta.md). Output only: reading .xmt (XMT-Ω, and XMT-A by its root
// element) is format_xmto.cpp's.
//  - ".xmt" (kind "xmt"): the face scene with the FBA stream's object descriptor; its StreamSource
//    names the .mp4 of the same stem, track 10, which `fapc compile` writes from the same input.
//  - ".bifs.xmt" (kind "xmt-bifs", also `--to xmt-bifs`): the animation as timed BIFS Replace
//    commands on the FAP node's fields, for players without an FBA decoder.
#include <filesystem>
#include <optional>

#include "fapc/audio_codec/aac.hpp"
#include "fapc/audio_codec/codes.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "fapc/mpeg4/xmta_writer.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<std::string> write_fba_scene(const Loaded& loaded, const std::string& path, const ConvertOptions&) {
  std::string source, voice_source;
  if (path != "-") {  // "out/face.xmt" names "face.mp4", beside it
    const std::string mp4 = std::filesystem::path(path).stem().string() + ".mp4#";
    source = mp4 + std::to_string(mpeg4::kFbaTrackId);
    voice_source = mp4 + std::to_string(mpeg4::kAudioTrackId);
  }
  // The voice as the .mp4 of the same input carries it (the same configuration, track 11).
  std::optional<mpeg4::XmtaAudio> voice;
  if (loaded.audio && !loaded.audio->samples.empty()) {
    auto config = audio_codec::aac_lc_mono_config(loaded.audio->sample_rate);
    if (config.empty())
      return make_error(
          codes::aac::sample_rate,
          loaded.audio->source.file.empty() ? Location::whole_file(loaded.named(path)) : loaded.audio->source,
          "audio at " + std::to_string(loaded.audio->sample_rate) + " Hz has no AAC sampling frequency index");
    voice = mpeg4::XmtaAudio{std::move(config), static_cast<std::uint32_t>(loaded.audio->sample_rate), voice_source};
  }
  return mpeg4::write_xmta_fba_scene(mpeg4::fba_decoder_specific_info(), source, voice ? &*voice : nullptr);
}

Result<std::string> write_bifs_commands(const Loaded& loaded, const std::string&, const ConvertOptions&) {
  return mpeg4::write_xmta_commands(loaded.frames);
}

}  // namespace

OutputFormat xmta_scene_output() {
  OutputFormat format{"xmt", {".xmt"}, write_fba_scene};
  format.uses_audio = true;  // the voice's configuration
  return format;
}
OutputFormat xmta_commands_output() { return {"xmt-bifs", {".bifs.xmt"}, write_bifs_commands}; }

}  // namespace fapc::pipeline::builtin

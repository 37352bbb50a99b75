// XMT-A outputs (docs/mp4-and-xmta.md). Output only: reading .xmt (XMT-Ω, and XMT-A by its root
// element) is format_xmto.cpp's.
//  - ".xmt" (kind "xmt"): the face scene with the FBA stream's object descriptor; its StreamSource
//    names the .mp4 of the same stem, track 10, which `fapc compile` writes from the same input.
//  - ".bifs.xmt" (kind "xmt-bifs", also `--to xmt-bifs`): the animation as timed BIFS Replace
//    commands on the FAP node's fields, for players without an FBA decoder.
#include <filesystem>

#include "fapc/mpeg4/mp4_writer.hpp"
#include "fapc/mpeg4/xmta_writer.hpp"
#include "formats.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<std::string> write_fba_scene(const Loaded&, const std::string& path, const ConvertOptions&) {
  std::string source;
  if (path != "-")  // "out/face.xmt" names "face.mp4", beside it
    source = std::filesystem::path(path).stem().string() + ".mp4#" + std::to_string(xmt::kFbaTrackId);
  return xmt::write_xmta_fba_scene(xmt::fba_decoder_specific_info(), source);
}

Result<std::string> write_bifs_commands(const Loaded& loaded, const std::string&, const ConvertOptions&) {
  return xmt::write_xmta_commands(loaded.frames);
}

}  // namespace

OutputFormat xmta_scene_output() { return {"xmt", {".xmt"}, write_fba_scene}; }
OutputFormat xmta_commands_output() { return {"xmt-bifs", {".bifs.xmt"}, write_bifs_commands}; }

}  // namespace fapc::pipeline::builtin

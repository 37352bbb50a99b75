// BIFS (ISO/IEC 14496-11) coding of the project's scenes: the version 1 BIFSConfig of a scene
// stream's decoder configuration, and a scene access unit holding one SceneReplace command.
// Only the node subset of scene.hpp is coded; anything else is reported, never guessed.
#pragma once

#include <cstdint>
#include <string>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/mpeg4/fba_track.hpp"
#include "fapc/mpeg4/scene.hpp"

namespace fapc::xmt {

// BIFSConfig for BIFS version 1 (scene objectTypeIndication 1). The defaults are those of the
// project's scene: 2-bit node IDs, no routes, a command stream without pixel metrics and with a
// 320x240 size (GPAC writes exactly these bytes for the same settings: docs/mp4-and-xmta.md
// section 6.4).
struct BifsConfig {
  int node_id_bits = 2;
  int route_id_bits = 0;
  bool command_stream = true;
  bool pixel_metric = false;
  bool has_size = true;
  std::uint16_t width = 320;
  std::uint16_t height = 240;
  friend bool operator==(const BifsConfig&, const BifsConfig&) = default;
};

Bytes encode_bifs_config(const BifsConfig& config);
Result<BifsConfig> decode_bifs_config(const Bytes& bytes, std::uint64_t base, const std::string& file);

// One access unit: SceneReplace of `top` (an SFTopNode), with DEF names kept (USENAMES) when
// `use_names`. DEF'd nodes get IDs 1, 2, ... in document order. Errors name the node or field
// the subset cannot code, or a node ID that does not fit config.node_id_bits.
Result<Bytes> encode_scene_replace(const SceneNode& top, const BifsConfig& config, bool use_names = true);

// The scene of an access unit that holds one SceneReplace command and nothing after it. Errors
// carry the file offset of the byte where decoding stopped.
Result<SceneNode> decode_scene_replace(const Bytes& bytes, const BifsConfig& config, std::uint64_t base,
                                       const std::string& file);

}  // namespace fapc::xmt

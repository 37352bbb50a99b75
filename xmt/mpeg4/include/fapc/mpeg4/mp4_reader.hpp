// Reads ISO base media files: the box tree (never reading outside the file or outside a box's
// parent; every error names the byte offset), the initial object descriptor, each track with its
// decoder configuration and sample table; then, on top, the project's view of an MPEG-4 face
// file: its scene, its object descriptors and its FBA track.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/mpeg4/audio_track.hpp"
#include "fapc/mpeg4/bifs.hpp"
#include "fapc/mpeg4/fba_track.hpp"
#include "fapc/mpeg4/object_descriptors.hpp"
#include "fapc/mpeg4/scene.hpp"

namespace fapc::xmt {

struct Mp4Sample {
  std::uint64_t offset = 0;  // in the file
  std::uint32_t size = 0;
  std::uint64_t decode_time = 0;  // in the track's timescale
  std::uint32_t duration = 0;
  bool sync = true;
};

// One entry of a track's edit list (edts/elst), version 0 or 1.
struct Mp4Edit {
  std::uint64_t duration = 0;    // in the movie's timescale
  std::int64_t media_time = -1;  // in the track's timescale; -1: an empty edit
  friend bool operator==(const Mp4Edit&, const Mp4Edit&) = default;
};

struct Mp4Track {
  std::uint64_t box_offset = 0;  // where its trak box starts
  std::uint32_t id = 0;
  std::string handler;  // "sdsm", "odsm", "vide", ...
  std::uint32_t timescale = 0;
  std::uint64_t duration = 0;       // in the track's timescale (mdhd)
  std::string sample_entry;         // "mp4v", "mp4s", ...
  std::optional<EsDescriptor> es;   // from the sample entry's esds box
  std::uint64_t es_offset = 0;      // file offset of that ES_Descriptor
  std::vector<std::uint32_t> mpod;  // tref/mpod: the tracks an OD stream's ES_ID_Refs index
  std::vector<Mp4Edit> edits;       // applied to the audio track only (see Mp4File::warnings)
  std::uint64_t edits_offset = 0;   // where the elst box starts
  std::vector<Mp4Sample> samples;
};

struct Mp4File {
  std::string file;  // the name used in diagnostics
  Bytes data;        // the whole file; samples point into it
  std::string major_brand;
  std::vector<std::string> compatible_brands;
  std::uint32_t timescale = 0;  // mvhd
  std::uint64_t duration = 0;
  std::optional<InitialObjectDescriptor> iod;
  std::vector<Mp4Track> tracks;
  Diagnostics warnings;  // boxes whose meaning the reader does not apply (edit lists other than
                         // an audio track's, fragments)

  const Mp4Track* track(std::uint32_t id) const;
  Bytes sample_bytes(const Mp4Sample& s) const;  // offsets were checked when reading
};

Result<Mp4File> read_mp4(Bytes data, const std::string& file);

// The project's view of the file.
struct Mp4SceneView {
  std::uint32_t track_id = 0;
  BifsConfig config;
  SceneNode scene;  // from the first access unit
};
struct Mp4ObjectView {
  ObjectDescriptor od;
  std::vector<std::uint32_t> track_ids;  // the ES_ID_Refs resolved through mpod
};

// The scene track's configuration and the scene of its first access unit.
Result<Mp4SceneView> read_scene(const Mp4File& mp4);
// The object descriptors of the OD track's first access unit, with their tracks.
Result<std::vector<Mp4ObjectView>> read_object_descriptors(const Mp4File& mp4);
// The FBA track (mp4v, stream type 4, object type 0x20) as the writer took it.
Result<FbaTrackInput> read_fba_track(const Mp4File& mp4);
// The FBA track, or nullptr when the file has none.
const Mp4Track* find_fba_track(const Mp4File& mp4);

// The MPEG-4 audio track (streamType 5, objectTypeIndication 0x40), or nullptr.
const Mp4Track* find_audio_track(const Mp4File& mp4);
// That track as the writer took it: its access units, all of one duration; its edit list read as
// an optional empty edit (the delay) then one edit of the sound (priming skipped, length).
// Errors name the box or sample at fault; what the edit list cannot say is an error too
// (several sound edits, a rate other than 1, access units of different durations but the last).
Result<AudioTrackInput> read_audio_track(const Mp4File& mp4, const Mp4Track& track);

}  // namespace fapc::xmt

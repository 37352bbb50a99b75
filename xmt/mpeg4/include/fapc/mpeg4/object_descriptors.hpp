// The MPEG-4 object descriptor framework (ISO/IEC 14496-1) in the forms an MP4 file stores
// (ISO/IEC 14496-14): ES descriptors with their decoder configuration, the initial object
// descriptor of the `iods` box (MP4_IOD with ES_ID_Inc), and object descriptor updates whose
// MP4_OD descriptors point at streams through ES_ID_Ref.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/mpeg4/fba_track.hpp"

namespace fapc::xmt {

// Descriptor and command tags (14496-1 §7.2.2.1, 14496-14 §3.1).
inline constexpr std::uint8_t kObjectDescriptorUpdateTag = 0x01;
inline constexpr std::uint8_t kEsDescriptorTag = 0x03;
inline constexpr std::uint8_t kDecoderConfigTag = 0x04;
inline constexpr std::uint8_t kDecoderSpecificInfoTag = 0x05;
inline constexpr std::uint8_t kSlConfigTag = 0x06;
inline constexpr std::uint8_t kEsIdIncTag = 0x0E;
inline constexpr std::uint8_t kEsIdRefTag = 0x0F;
inline constexpr std::uint8_t kMp4IodTag = 0x10;
inline constexpr std::uint8_t kMp4OdTag = 0x11;

// Stream types and object type indications used by the project.
inline constexpr std::uint8_t kObjectDescriptorStream = 0x01;
inline constexpr std::uint8_t kSceneDescriptionStream = 0x03;
inline constexpr std::uint8_t kVisualStream = 0x04;
inline constexpr std::uint8_t kSystemsV1Object = 0x01;
inline constexpr std::uint8_t kVisual14496_2Object = 0x20;

// SL packet header configuration 2: the one MP4 files use (14496-14 §3.1.2).
inline constexpr std::uint8_t kSlPredefinedMp4 = 2;

struct DecoderConfig {
  std::uint8_t object_type = 0;  // objectTypeIndication
  std::uint8_t stream_type = 0;
  bool up_stream = false;
  std::uint32_t buffer_size = 0;  // bufferSizeDB, bytes (24 bits)
  std::uint32_t max_bitrate = 0;  // bits per second
  std::uint32_t avg_bitrate = 0;
  Bytes specific_info;  // DecoderSpecificInfo payload; empty when absent
  friend bool operator==(const DecoderConfig&, const DecoderConfig&) = default;
};

struct EsDescriptor {
  std::uint16_t es_id = 0;  // 0 inside MP4 files: the track ID stands for it
  DecoderConfig config;
  std::uint8_t sl_predefined = kSlPredefinedMp4;
  friend bool operator==(const EsDescriptor&, const EsDescriptor&) = default;
};

// profile_and_level indications of an initial object descriptor. 0xFE: no profile specified;
// 0xFF: no capability required.
struct ProfileLevels {
  std::uint8_t od = 0xFF;
  std::uint8_t scene = 0xFE;
  std::uint8_t audio = 0xFF;
  std::uint8_t visual = 0xFF;
  std::uint8_t graphics = 0xFE;
  friend bool operator==(const ProfileLevels&, const ProfileLevels&) = default;
};

struct InitialObjectDescriptor {
  std::uint16_t od_id = 1;  // 10 bits
  ProfileLevels profiles;
  std::vector<std::uint32_t> es_id_incs;  // track IDs of the streams it declares
  friend bool operator==(const InitialObjectDescriptor&, const InitialObjectDescriptor&) = default;
};

struct ObjectDescriptor {
  std::uint16_t od_id = 0;                // 10 bits
  std::vector<std::uint16_t> es_id_refs;  // 1-based indexes into the OD track's `mpod` reference
  friend bool operator==(const ObjectDescriptor&, const ObjectDescriptor&) = default;
};

// Encoders: the bytes of one descriptor (tag, size, payload), sizes in their shortest form.
Bytes encode_es_descriptor(const EsDescriptor& es);
Bytes encode_initial_object_descriptor(const InitialObjectDescriptor& iod);
// One ObjectDescriptorUpdate command carrying MP4_OD descriptors: an OD access unit.
Bytes encode_object_descriptor_update(const std::vector<ObjectDescriptor>& ods);

// Decoders. `base` is the file offset of bytes[0], so errors name file offsets. Descriptors the
// project does not use (IPMP, OCI, language...) are skipped by their size.
Result<EsDescriptor> decode_es_descriptor(const Bytes& bytes, std::uint64_t base, const std::string& file);
Result<InitialObjectDescriptor> decode_initial_object_descriptor(const Bytes& bytes, std::uint64_t base,
                                                                 const std::string& file);
// Every ObjectDescriptorUpdate in an OD access unit, flattened; other commands are an error.
Result<std::vector<ObjectDescriptor>> decode_object_descriptor_updates(const Bytes& bytes, std::uint64_t base,
                                                                       const std::string& file);

}  // namespace fapc::xmt

#include "fapc/mpeg4/fba_track.hpp"

#include "fapc/mpeg4/codes.hpp"

namespace fapc::mpeg4 {

namespace {

// 0010 0011 after the visual object start code: is_visual_object_identifier 0, visual_object_type
// 0100 (FBA), then next_start_code stuffing 0 11 (docs/mp4-and-xmta.md section 6.2).
constexpr std::uint8_t kFbaVisualObjectByte = 0x23;
constexpr std::uint8_t kStuffingWhenAligned = 0x7F;

void put_start_code(Bytes& out, std::uint8_t code) { out.insert(out.end(), {0x00, 0x00, 0x01, code}); }

bool starts_with_start_code(std::span<const std::uint8_t> bytes, std::uint8_t code) {
  return bytes.size() >= 4 && bytes[0] == 0 && bytes[1] == 0 && bytes[2] == 1 && bytes[3] == code;
}

}  // namespace

Bytes fba_decoder_specific_info(std::uint8_t profile_level) {
  Bytes out;
  put_start_code(out, kVisualObjectSequenceStartCode);
  out.push_back(profile_level);
  put_start_code(out, kVisualObjectStartCode);
  out.push_back(kFbaVisualObjectByte);
  put_start_code(out, kFbaObjectStartCode);
  return out;
}

Result<std::uint8_t> fba_profile_level(const Bytes& dsi, const std::string& file) {
  if (!starts_with_start_code(dsi, kVisualObjectSequenceStartCode) || dsi.size() < 5)
    return make_error(codes::mp4::bad_fba_config, Location::binary(file, 0),
                      "FBA decoder configuration does not start with a visual object sequence "
                      "header (00 00 01 B0 and a profile-level byte)");
  return dsi[4];
}

std::string_view fba_profile_name(std::uint8_t profile_level) {
  switch (profile_level) {
    case kSimpleFaceAnimationL1:
      return "Simple Face Animation @ L1";
    case kSimpleFaceAnimationL2:
      return "Simple Face Animation @ L2";
    case kSimpleFbaL1:
      return "Simple FBA @ L1";
    case kSimpleFbaL2:
      return "Simple FBA @ L2";
    default:
      return "";
  }
}

bool declares_fba_object(const Bytes& dsi) {
  constexpr std::uint32_t kFbaObjectType = 4;
  for (std::size_t i = 0; i + 5 < dsi.size(); ++i) {
    if (dsi[i] != 0 || dsi[i + 1] != 0 || dsi[i + 2] != 1 || dsi[i + 3] != kVisualObjectStartCode) continue;
    const std::uint32_t bits = (std::uint32_t{dsi[i + 4]} << 8) | dsi[i + 5];
    // is_visual_object_identifier, then (when set) 4 bits of verid and 3 of priority.
    const bool identified = (bits & 0x8000) != 0;
    return ((identified ? bits >> 4 : bits >> 11) & 0xF) == kFbaObjectType;
  }
  return false;
}

FbaTrackView view_of(const FbaTrackInput& track) {
  FbaTrackView view{track.decoder_specific_info, track.timescale, {}};
  view.samples.reserve(track.samples.size());
  for (const FbaSample& s : track.samples) view.samples.push_back({s.bytes, s.duration, s.sync});
  return view;
}

Status check_fba_track(const FbaTrackInput& track) { return check_fba_track(view_of(track)); }

Status check_fba_track(const FbaTrackView& track) {
  if (auto pl = fba_profile_level(track.decoder_specific_info); !pl) return pl.error();
  if (track.timescale == 0) return make_error(codes::mp4::bad_fba_track, Location{}, "FBA track timescale is 0");
  if (track.samples.empty()) return make_error(codes::mp4::bad_fba_track, Location{}, "FBA track has no samples");
  for (std::size_t i = 0; i < track.samples.size(); ++i) {
    const FbaSampleView& s = track.samples[i];
    if (!starts_with_start_code(s.bytes, kFbaObjectPlaneStartCode))
      return make_error(
          codes::mp4::bad_fba_track, Location{},
          "FBA sample " + std::to_string(i + 1) + " does not start with the plane start code 00 00 01 BB");
    if (s.duration == 0)
      return make_error(codes::mp4::bad_fba_track, Location{},
                        "FBA sample " + std::to_string(i + 1) + " lasts 0 ticks");
  }
  return ok_status();
}

Bytes fba_stream_from_track(const FbaTrackInput& track) {
  Bytes out = track.decoder_specific_info;
  out.push_back(kStuffingWhenAligned);
  for (const FbaSample& s : track.samples) out.insert(out.end(), s.bytes.begin(), s.bytes.end());
  put_start_code(out, kVisualObjectSequenceEndCode);
  return out;
}

}  // namespace fapc::mpeg4

// Every start code, field width and table of the FBA bitstream that encoder and decoder share,
// named once (docs/fba-bitstream.md sections 5, 7 and appendix A). Private to fapcodec.
#pragma once

#include <array>
#include <cstdint>

namespace fapc::fba {

// Start codes, 32 bits each (section 5.1).
inline constexpr int kStartCodeBits = 32;
inline constexpr std::uint32_t kStartCodePrefix = 0x000001;  // the top 24 bits of every start code
inline constexpr std::uint32_t kVisualObjectSequenceStartCode = 0x000001B0;
inline constexpr std::uint32_t kVisualObjectSequenceEndCode = 0x000001B1;
inline constexpr std::uint32_t kUserDataStartCode = 0x000001B2;
inline constexpr std::uint32_t kVisualObjectStartCode = 0x000001B5;
inline constexpr std::uint32_t kFbaObjectStartCode = 0x000001BA;
inline constexpr std::uint32_t kFbaObjectPlaneStartCode = 0x000001BB;
inline constexpr std::uint32_t kLegacyObjectStartCode = 0x00000101;  // accepted, never written
inline constexpr std::uint32_t kLegacyPlaneStartCode = 0x00000103;   // accepted, never written
inline constexpr std::uint8_t kStuffingByte = 0x7F;

// Visual object sequence and visual object headers (section 5.1; MP4 tracks carry them in their
// decoder configuration).
inline constexpr int kProfileLevelBits = 8;
inline constexpr std::uint8_t kSimpleFbaLevel1 = 0x63;
inline constexpr int kVisualObjectVerIdBits = 4;
inline constexpr int kVisualObjectPriorityBits = 3;
inline constexpr int kVisualObjectTypeBits = 4;
inline constexpr std::uint32_t kVisualObjectTypeFba = 4;

// Plane header and temporal header (section 5.3).
inline constexpr int kObjectMaskBits = 2;
inline constexpr std::uint32_t kObjectMaskFace = 1;  // bit 0: FAP data
inline constexpr std::uint32_t kObjectMaskBody = 2;  // bit 1: BAP data
inline constexpr int kFrameRateBits = 8;
inline constexpr int kFrameRateSecondsBits = 4;  // sixteenths added to frame_rate
inline constexpr int kTimeCodeHoursBits = 5;
inline constexpr int kTimeCodeMinutesBits = 6;
inline constexpr int kTimeCodeSecondsBits = 6;
inline constexpr int kSkipChunkBits = 4;
inline constexpr std::uint32_t kSkipChunkContinues = 15;  // a chunk of 15 means "more follow"

// Face data (sections 5.4 to 5.6).
inline constexpr int kFapQuantBits = 5;
inline constexpr int kMaxFapQuant = 31;
inline constexpr int kMaskTypeBits = 2;
enum MaskType : std::uint32_t { kMaskNone = 0, kMaskListed = 1, kMaskListedInterpolate = 2, kMaskAll = 3 };
inline constexpr int kRangeValueBits = 5;
inline constexpr int kMaxRangeValue = 31;
inline constexpr int kRangeDelta = 60;  // ranges travel in steps of 60 quantised units
inline constexpr int kMarkerEvery = 4;  // a marker bit before every 4th entry of a group's list
enum RangeList { kIntraMax = 0, kIntraMin = 1, kPredMax = 2, kPredMin = 3 };
inline constexpr int kRangeListCount = 4;
inline constexpr int kFirstLowLevelFap = 3;

// FAP 1 and FAP 2 fields coded in the segments (section 6.8), in coding order.
inline constexpr int kCodedFieldCount = 7;
inline constexpr int kVisemeFields = 3;      // select1, select2, blend
inline constexpr int kExpressionFields = 4;  // select1, intensity1, select2, intensity2
// The largest viseme_blend and expression intensity (docs/fap-table.md section 4).
inline constexpr int kLargestFieldValue = 63;
inline constexpr std::array<int, kCodedFieldCount> kFieldLimit{14, 14, -1, 6, -1, 6, -1};  // -1: B

// Body data, parsed only (docs/fba-bitstream.md section 5.8, appendix A).
inline constexpr int kBapGroupCount = 24;
inline constexpr std::array<int, kBapGroupCount> kBapGroupSizes{3,  4,  4,  6,  6,  5,  5, 7,  7,  12, 15, 18,
                                                                18, 12, 16, 16, 13, 13, 6, 22, 22, 22, 22, 22};
inline constexpr int kBapCount = 296;
inline constexpr int kBapQuantBits = 5;
inline constexpr std::array<int, 32> kBapPredScale{0,  1,  2,  3,  5,  7,  9,  11, 14, 17, 20, 23,  27,  31,  35,  39,
                                                   43, 47, 52, 57, 62, 67, 72, 77, 82, 88, 94, 100, 106, 113, 120, 127};

}  // namespace fapc::fba

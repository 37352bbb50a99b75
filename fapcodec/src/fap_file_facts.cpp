// How `fapc info` names what the .fap reader saw.
#include "fapc/codec/fap_file.hpp"

namespace fapc {

std::string FapFileFacts::variant() const {
  if (!has_header)
    return millisecond_stamps ? "SEMAINE (no header, millisecond time stamps)" : "SEMAINE (no header, frame indices)";
  if (version == "2.0") return "VREng 2.0";
  if (mask_69_tokens) return "Greta (69-token masks)";
  if (comment_lines > 0) return "VREng (leading comment)";
  if (header_name.find('\\') != std::string::npos || header_name.find(':') != std::string::npos)
    return "Xface (exml2fap)";
  return "baseline " + version;
}

std::vector<std::string> FapFileFacts::deviations() const {
  std::vector<std::string> out;
  const auto add = [&](bool present, const char* text) {
    if (present) out.emplace_back(text);
  };
  add(crlf, "CRLF line ends");
  add(trailing_spaces, "trailing spaces");
  add(!final_newline, "no newline at end of file");
  add(comment_lines > 0, "comment lines");
  add(utf8_bom, "UTF-8 byte-order mark");
  add(header_name.find(' ') != std::string::npos, "header name contains a space");
  add(header_name.find_first_of("/\\") != std::string::npos, "header name is a path");
  add(has_header && version != "2.1", "version other than 2.1");
  add(tabs, "tab-separated values");
  add(mask_69_tokens, "69-token mask lines");
  add(fap12_single_values, "FAP 1/FAP 2 as single values");
  add(fap12_full_fields, "FAP 1/FAP 2 as 4/6 values");
  add(!has_header, "no header");
  add(semaine_time_line, "leading time line");
  add(millisecond_stamps, "millisecond time stamps as frame numbers");
  add(frames_from_one, "frames numbered from 1");
  add(frame_gaps, "absent frames");
  add(float_values, "non-integer values");
  add(zero_active_faps, "frames with no active FAP");
  return out;
}

}  // namespace fapc

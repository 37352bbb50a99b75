// What each bridge output cannot carry of a given animation, named in a warning.
#include "bases.hpp"
#include "fapc/codec/fap_table.hpp"
#include "fapc/face/face_track.hpp"
#include "fapc/pipeline/codes.hpp"
#include "writers.hpp"

namespace fapc::pipeline::bridges {
namespace {

std::string fap_list(const std::vector<int>& faps) {
  constexpr std::size_t kShown = 8;
  std::string out;
  for (std::size_t i = 0; i < faps.size() && i < kShown; ++i) {
    out += (i ? ", " : "") + std::to_string(faps[i]) + " " + std::string(find_fap(faps[i])->name);
  }
  if (faps.size() > kShown) out += " and " + std::to_string(faps.size() - kShown) + " more";
  return out;
}

Diagnostic lost(const std::string& output, WarningCode code, const std::string& message) {
  return make_warning(code, Location::whole_file(output), message);
}

}  // namespace

Diagnostics losses(const FapSequence& frames, Carrier carrier, const std::string& output) {
  Diagnostics out;
  if (carrier == Carrier::visemes) {
    bool any_viseme = false;
    std::bitset<kFapCount> others;
    for (const FapFrame& frame : frames.frames) {
      any_viseme = any_viseme || frame.has(1);
      others |= frame.mask;
    }
    others.reset(0);
    std::vector<int> faps;
    for (int fap = 2; fap <= kFapCount; ++fap)
      if (others.test(static_cast<std::size_t>(fap - 1))) faps.push_back(fap);
    if (!any_viseme) {
      out.push_back(
          lost(output, codes::visemes::no_viseme, "no frame sends FAP 1 (viseme): the track is silence throughout"));
    }
    if (!faps.empty()) {
      out.push_back(
          lost(output, codes::visemes::faps_lost,
               "a viseme track carries FAP 1 only (the heavier of its two visemes); lost: FAPs " + fap_list(faps)));
    }
    return out;
  }
  const bool arkit = carrier == Carrier::arkit;
  const std::bitset<kFapCount> carried = arkit ? carried_by_arkit_csv() : carried_by_openface_csv();
  std::vector<int> faps;
  for (int fap : face::FaceTrack(frames).moving_faps())
    if (!carried.test(static_cast<std::size_t>(fap - 1))) faps.push_back(fap);
  if (!faps.empty()) {
    out.push_back(lost(output, arkit ? codes::arkit_csv::faps_lost : codes::openface_csv::faps_lost,
                       std::string(arkit ? "ARKit's shapes" : "OpenFace's 17 action units") + " cannot carry FAPs " +
                           fap_list(faps) + "; they are lost"));
  }
  return out;
}

}  // namespace fapc::pipeline::bridges

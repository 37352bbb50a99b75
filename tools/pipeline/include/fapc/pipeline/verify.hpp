// Verify: what `fapc verify` checks. A .fba stream decodes, and encoding its frames again with
// the settings it shows gives the same bytes (true of every stream fapc writes; the settings the
// bits do not show are searched for). An .mp4: the same for its FBA track, sample by sample,
// durations and sync flags included. Any other input: it encodes with the given settings, the
// stream decodes to within half a quantiser step (exactly at quant 0) and re-encodes the same.
#pragma once

#include <optional>
#include <string>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::pipeline {

struct VerifyResult {
  Diagnostics warnings;             // the reader's
  std::optional<Diagnostic> error;  // verification_failed when a check fails; else why it could not run
  std::string summary;              // "N frames, B bytes, X bits/frame at fap_quant Q" when ok
  // The same figures as fields (docs/json.md), when ok.
  std::size_t frames = 0;
  std::size_t bytes = 0;
  double bits_per_frame = 0;
  int quant = 0;
  // The largest |decoded - input| over FAPs 3-68, in FAP units: for inputs that are encoded here;
  // absent for .fba and .mp4, whose check is that re-encoding gives the same bytes.
  std::optional<long long> max_error;
  bool ok() const { return !error; }
};

VerifyResult verify(const std::string& path, const ConvertOptions& options);

}  // namespace fapc::pipeline

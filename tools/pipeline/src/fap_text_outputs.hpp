// The .fap text of a streamed conversion, made as the frames come and handed in pieces to a
// temporary file per .fap output (AtomicFile): an output appears only when committed, so an error
// found late leaves nothing. The .fap row's frame writer uses it (formats/format_fap.cpp); the
// option and error helpers serve the loaded .fap writer too. Private to the pipeline.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::pipeline {

// --fap-flavour as the writer's options.
FapWriteOptions fap_write_options(const ConvertOptions& options);
// The .fap writer's error (a frame or a rate the flavour cannot carry) as writing `path` gives it.
Diagnostic fap_writer_error_at(const Diagnostic& error, const std::string& path);

class FapTextOutputs {
 public:
  // The header's facts: the sequence's name, rate, frame count and first and last frame numbers.
  FapTextOutputs(const std::string& name, int fps, std::size_t frames, std::int64_t first_number,
                 std::int64_t last_number, const ConvertOptions& options);

  // A temporary file for output `i`; its error, if any, is that output's.
  void open(std::size_t i, const std::string& path);
  bool any() const { return !files_.empty(); }

  void begin();
  void add(const FapFrame& frame);
  void finish();

  // The error writing output `i` (at `path`) meets, if any: the flavour's, else the file's.
  std::optional<Diagnostic> error_of(std::size_t i, const std::string& path) const;
  Status commit(std::size_t i);

 private:
  void flush();

  FapTextWriter writer_;
  std::string text_;                                        // made, not yet written
  std::optional<Diagnostic> error_;                         // the writer's: the flavour cannot carry a frame
  std::vector<std::pair<std::size_t, AtomicFile>> files_;   // by output index
  std::vector<std::pair<std::size_t, Diagnostic>> failed_;  // outputs whose file failed
};

// The error of --strict when the input gave warnings: nothing is written.
Diagnostic strict_error(const std::string& input, std::size_t warnings);

}  // namespace fapc::pipeline

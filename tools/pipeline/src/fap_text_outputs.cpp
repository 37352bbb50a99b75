#include "fap_text_outputs.hpp"

#include <algorithm>

#include "fapc/pipeline/codes.hpp"

namespace fapc::pipeline {

FapWriteOptions fap_write_options(const ConvertOptions& options) {
  FapWriteOptions write;
  write.flavour = options.fap_flavour;
  return write;
}

Diagnostic fap_writer_error_at(const Diagnostic& error, const std::string& path) {
  return retold(error, Location::whole_file(path), error.message);
}

FapTextOutputs::FapTextOutputs(const std::string& name, int fps, std::size_t frames, std::int64_t first_number,
                               std::int64_t last_number, const ConvertOptions& options)
    : writer_(name, fps, frames, first_number, last_number, fap_write_options(options)) {}

void FapTextOutputs::open(std::size_t i, const std::string& path) {
  auto file = AtomicFile::create(path);
  if (file)
    files_.emplace_back(i, std::move(*file));
  else
    failed_.emplace_back(i, file.error());
}

void FapTextOutputs::begin() {
  if (auto status = writer_.begin(text_); !status) error_ = status.error();
}

void FapTextOutputs::add(const FapFrame& frame) {
  if (error_) return;
  if (auto status = writer_.add(frame, text_); !status)
    error_ = status.error();
  else if (text_.size() >= (std::size_t{1} << 20))
    flush();
}

void FapTextOutputs::finish() {
  if (error_) return;
  writer_.finish(text_);
  flush();
}

std::optional<Diagnostic> FapTextOutputs::error_of(std::size_t i, const std::string& path) const {
  if (error_) return fap_writer_error_at(*error_, path);
  for (const auto& [at, why] : failed_)
    if (at == i) return why;
  return std::nullopt;
}

Status FapTextOutputs::commit(std::size_t i) {
  for (auto& [at, file] : files_)
    if (at == i) return file.commit();
  return ok_status();  // not reached: every .fap output has a file or an error
}

void FapTextOutputs::flush() {
  for (auto& entry : files_) {  // not a structured binding: clang 14 cannot capture one
    const std::size_t i = entry.first;
    const bool failed_before = std::any_of(failed_.begin(), failed_.end(), [i](const auto& f) { return f.first == i; });
    if (auto written = entry.second.write(text_); !written && !failed_before) failed_.emplace_back(i, written.error());
  }
  text_.clear();
}

Diagnostic strict_error(const std::string& input, std::size_t warnings) {
  return make_error(codes::output::strict_warnings, Location::whole_file(input),
                    std::to_string(warnings) + " warning(s) treated as errors (--strict); nothing written");
}

}  // namespace fapc::pipeline

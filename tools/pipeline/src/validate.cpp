#include "fapc/pipeline/validate.hpp"

#include "fapc/codec/file_io.hpp"

namespace fapc::pipeline {

Result<xml::ValidationReport> validate(const std::string& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return xml::validate_xml(*bytes, path);
}

}  // namespace fapc::pipeline

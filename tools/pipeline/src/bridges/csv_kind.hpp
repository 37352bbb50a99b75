// Which CSV a .csv input is, decided by its header line alone: OpenFace's, ARKit's, or fapc's own
// frames CSV (an output of `fapc plot` and `compile`, which is not read back) (docs/bridges.md,
// "Inputs: OpenFace and ARKit CSVs").
#pragma once

#include <string>
#include <string_view>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::pipeline::bridges {

enum class CsvKind { openface, arkit };

Result<CsvKind> csv_kind(std::string_view text, const std::string& file);

}  // namespace fapc::pipeline::bridges

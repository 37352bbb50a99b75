// The readers and writers of today's face data (docs/bridges.md): OpenFace and ARKit CSVs in and
// out, and the viseme track. Listed in src/registry.cpp like the others.
#pragma once

#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

InputFormat tracker_csv_input();  // .csv: OpenFace or ARKit, by its header
InputFormat openface_csv_input();
InputFormat arkit_csv_input();

OutputFormat arkit_csv_output();
OutputFormat openface_csv_output();
OutputFormat viseme_json_output();
OutputFormat viseme_csv_output();

}  // namespace fapc::pipeline::builtin

// The JSON the program prints (`info --json`, `verify --json`, `batch --report-json`, errors
// under --json), built here so that its shape is one contract: docs/json.md, with a JSON Schema
// per document in docs/json/. Keys are snake_case; every figure is a field of its own.
// Part of the pipeline's kit (not installed): the program and the pipeline build these documents.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/pipeline/batch.hpp"
#include "fapc/pipeline/batch_shard.hpp"
#include "fapc/pipeline/verify.hpp"

namespace fapc::pipeline {

// Raised when a key is renamed or removed or a meaning changes; new keys do not raise it.
inline constexpr int kJsonSchemaVersion = 1;

// {"severity", "kind" (errors; null for warnings), "file", "line", "column", "byte" (null when not
// known), "message", "text" (the one-line form of docs/cli.md)}.
nlohmann::ordered_json diagnostic_json(const Diagnostic& d);
nlohmann::ordered_json diagnostics_json(const Diagnostics& ds);

// What a command prints on standard output under --json when it fails before it has a result:
// {"schema_version", "error": diagnostic}.
nlohmann::ordered_json error_document(const Diagnostic& d);

// `verify --json`: {"schema_version", "files": [one object per file, in order]}.
nlohmann::ordered_json verify_file_json(const std::string& path, const VerifyResult& result, int exit_status);
nlohmann::ordered_json verify_document(std::vector<nlohmann::ordered_json> files);

// `batch --report-json`: {"schema_version", "shard", "planned", "jobs": [...], "totals": {...}}.
// `planned`: the jobs of the whole batch, all shards together (without a shard, jobs.size()).
nlohmann::ordered_json batch_report_json(const std::vector<BatchJob>& jobs, const std::vector<BatchOutcome>& outcomes,
                                         bool interrupted, const std::optional<Shard>& shard = std::nullopt,
                                         std::size_t planned = 0);

}  // namespace fapc::pipeline

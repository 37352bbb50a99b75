#include "fapc/pipeline/batch_resume.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/codes.hpp"

namespace fapc::pipeline {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

// The target a temporary output was for: ".fapc-tmp-<pid>-<seed>-<n>-<name>" (fapcodec's
// file_io.cpp names them so) gives <name>; anything else gives an empty name.
std::string temporary_target(const std::string& file) {
  static const std::string prefix = ".fapc-tmp-";
  if (!file.starts_with(prefix)) return {};
  std::size_t at = prefix.size();
  for (int field = 0; field < 3; ++field) {
    const std::size_t start = at;
    while (at < file.size() && file[at] >= '0' && file[at] <= '9') ++at;
    if (at == start || at >= file.size() || file[at] != '-') return {};
    ++at;
  }
  return file.substr(at);
}

json stamp_json(const FileStamp& stamp) { return {{"size", stamp.size}, {"time", stamp.time}}; }

bool same_stamp(const json& recorded, const std::optional<FileStamp>& now) {
  return now && recorded.is_object() && recorded.value("size", std::uintmax_t{0}) == now->size &&
         recorded.value("time", std::int64_t{0}) == now->time && recorded.contains("size") && recorded.contains("time");
}

}  // namespace

std::optional<FileStamp> stamp_of(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::is_regular_file(status)) return std::nullopt;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return std::nullopt;
  const fs::file_time_type time = fs::last_write_time(path, ec);
  if (ec) return std::nullopt;
  return FileStamp{size, static_cast<std::int64_t>(time.time_since_epoch().count())};
}

CompletionRecords::CompletionRecords(std::string out_dir, std::string settings, const std::vector<BatchJob>& jobs)
    : out_dir_(std::move(out_dir)), settings_(std::move(settings)) {
  for (const BatchJob& job : jobs) {
    for (const OutputRequest& output : job.outputs) {
      const fs::path path(output.path);
      ours_[path.parent_path().string()].insert(path.filename().string());
    }
    const fs::path record(record_path(job));
    ours_[record.parent_path().string()].insert(record.filename().string());
  }
}

std::string CompletionRecords::record_path(const BatchJob& job) const {
  const std::string first = job.outputs.empty() ? fs::path(job.input).filename().string() : job.outputs.front().path;
  fs::path base = fs::path(out_dir_).lexically_normal();
  if (base.has_relative_path() && !base.has_filename()) base = base.parent_path();  // "out/" is "out"
  const fs::path relative = fs::path(first).lexically_relative(base);
  // Planned outputs are always under DIR; a path that is not (a caller's own jobs) keeps its name.
  const fs::path name = relative.empty() || *relative.begin() == ".." ? fs::path(first).filename() : relative;
  return (fs::path(out_dir_) / kRecordsFolder / name).string() + ".done";
}

bool CompletionRecords::complete(const BatchJob& job) const {
  std::ifstream file(record_path(job), std::ios::binary);
  if (!file) return false;
  std::ostringstream text;
  text << file.rdbuf();
  const json record = json::parse(text.str(), nullptr, false);
  if (record.is_discarded() || !record.is_object() || record.value("settings", std::string()) != settings_ ||
      record.value("input", std::string()) != job.input || !record.contains("outputs") ||
      !record["outputs"].is_array() || record["outputs"].size() != job.outputs.size())
    return false;
  const std::optional<FileStamp> input = stamp_of(job.input);
  if (!same_stamp(record.value("input_stamp", json()), input)) return false;
  for (std::size_t i = 0; i < job.outputs.size(); ++i) {
    const json& output = record["outputs"][i];
    if (!output.is_object() || output.value("path", std::string()) != job.outputs[i].path ||
        output.value("kind", std::string()) != job.outputs[i].kind)
      return false;
    const std::optional<FileStamp> now = stamp_of(job.outputs[i].path);
    // Not also "no older than the input": the record's stamps already say the input is the one
    // converted, and on a shared file system the clocks of the writing nodes may disagree.
    if (!same_stamp(output.value("stamp", json()), now)) return false;
  }
  return true;
}

void CompletionRecords::sweep(const std::string& folder) const {
  {
    const std::lock_guard<std::mutex> lock(swept_lock_);
    if (!swept_.insert(folder).second) return;
  }
  const auto names = ours_.find(folder);
  if (names == ours_.end()) return;
  const std::string own_prefix = own_temporary_prefix();
  std::error_code ec;
  for (fs::directory_iterator it(folder.empty() ? "." : folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const std::string target = temporary_target(name);
    // Only this process's jobs' targets: another shard writing into the same folder keeps its own.
    // Nor this process's own temporary files: another thread may be writing one (a job started
    // while this sweep still walks the folder), and a killed run's have another prefix.
    std::error_code entry_ec;
    if (!target.empty() && names->second.count(target) && !name.starts_with(own_prefix) &&
        it->is_regular_file(entry_ec))
      fs::remove(it->path(), entry_ec);
  }
}

std::optional<FileStamp> CompletionRecords::prepare(const BatchJob& job) const {
  const std::string record = record_path(job);
  std::error_code ec;
  fs::remove(record, ec);
  sweep(fs::path(record).parent_path().string());
  for (const OutputRequest& output : job.outputs) sweep(fs::path(output.path).parent_path().string());
  return stamp_of(job.input);
}

Status CompletionRecords::record(const BatchJob& job, const std::optional<FileStamp>& input) const {
  const std::string path = record_path(job);
  const auto failed = [&](const std::string& why) {
    return make_error(codes::batch::record_not_written, Location::whole_file(path),
                      "cannot write the completion record: " + why);
  };
  if (!input) return failed("the input " + job.input + " is no longer a readable file");
  json outputs = json::array();
  for (const OutputRequest& output : job.outputs) {
    const std::optional<FileStamp> stamp = stamp_of(output.path);
    if (!stamp) return failed("the output " + output.path + " is not there");
    outputs.push_back({{"path", output.path}, {"kind", output.kind}, {"stamp", stamp_json(*stamp)}});
  }
  const json record = {{"input", job.input},
                       {"input_stamp", stamp_json(*input)},
                       {"settings", settings_},
                       {"outputs", std::move(outputs)}};
  std::error_code ec;
  fs::create_directories(fs::path(path).parent_path(), ec);
  if (ec) return failed(ec.message());
  return write_file_atomic(path, record.dump() + "\n");
}

}  // namespace fapc::pipeline

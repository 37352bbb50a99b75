// Several BML documents given in order (docs/bml.md, "Several blocks"): a list of documents, one
// per line, each a block sent to one realizer. Each block is read and placed by its composition
// after the blocks before it (block_reader.hpp); a REPLACE block first cuts what the earlier
// blocks still run at its start. The blocks' clips, sound, behaviours and marks make one document.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bml/block_reader.hpp"
#include "bml/sync_ref.hpp"
#include "fapc/bml/bml.hpp"
#include "fapc/bml/codes.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/xml/text.hpp"

namespace fapc::bml {
namespace {

// One line of the list: a document and, when the line says so, when it is sent.
struct ListedDocument {
  std::string name;
  Location where;  // the path's place in the list
  std::optional<double> at;
  Location at_where;
};

// `[at SECONDS] PATH` per line; blank lines and `#` lines are skipped.
Result<std::vector<ListedDocument>> parse_list(std::string_view text, const std::string& list_name,
                                               std::int64_t max_documents) {
  std::vector<ListedDocument> out;
  int line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line[first] == '#') continue;
    ListedDocument d;
    std::size_t path_at = first;
    if (line.substr(first).starts_with("at ") || line.substr(first).starts_with("at\t")) {
      const std::size_t number_at = line.find_first_not_of(" \t", first + 2);
      const std::size_t number_end =
          number_at == std::string_view::npos ? line.size() : line.find_first_of(" \t", number_at);
      d.at_where = Location::text(list_name, line_number, static_cast<int>(first) + 1);
      const auto seconds = number_at == std::string_view::npos
                               ? std::nullopt
                               : parse_seconds(line.substr(number_at, number_end - number_at));
      if (!seconds || *seconds < 0)
        return make_error(codes::bml::bad_sequence, d.at_where,
                          "'at' needs the time the block is sent, seconds from 0 on, then the document",
                          std::string(line));
      d.at = *seconds;
      path_at = number_end == std::string_view::npos ? line.size() : line.find_first_not_of(" \t", number_end);
      if (path_at == std::string_view::npos) path_at = line.size();
    }
    d.name = std::string(xml::trim(line.substr(path_at)));
    d.where = Location::text(list_name, line_number, static_cast<int>(path_at) + 1);
    if (d.name.empty())
      return make_error(codes::bml::bad_sequence, d.where, "a time with no document after it", std::string(line));
    // A NUL would end the name early when the file is opened: another file than the one written.
    const auto control =
        std::find_if(d.name.begin(), d.name.end(), [](unsigned char c) { return c < 0x20 && c != '\t'; });
    if (control != d.name.end())
      return make_error(
          codes::bml::bad_sequence,
          Location::text(list_name, line_number, static_cast<int>(path_at + (control - d.name.begin())) + 1),
          "a control character in a document's path", std::string(line));
    if (static_cast<std::int64_t>(out.size()) >= max_documents) {
      return make_error(
          codes::limit::runs, d.where,
          "more than " + std::to_string(max_documents) + " documents and behaviours (raise the limit with --max-runs)",
          std::string(line));
    }
    out.push_back(std::move(d));
  }
  if (out.empty())
    return make_error(codes::bml::bad_sequence, Location::text(list_name, 1, 1), "no BML document in this list");
  return out;
}

// REPLACE: what the earlier blocks still run at `cut` ends there; what they would start later
// never starts. A shift that ended before keeps its held state (the new rest, not a running
// behaviour). Returns how many behaviours never started, and the first of them.
std::pair<std::size_t, std::string> cut_at(BmlDocument& doc, double cut) {
  std::vector<Clip>& clips = doc.timeline.clips;
  clips.erase(std::remove_if(clips.begin(), clips.end(), [&](const Clip& c) { return c.begin >= cut; }), clips.end());
  for (Clip& c : clips)
    if (c.end > cut) {
      c.end = cut;
      c.fill = Fill::remove;
    }
  std::vector<AudioClip>& audio = doc.timeline.audio;
  audio.erase(std::remove_if(audio.begin(), audio.end(), [&](const AudioClip& a) { return a.begin >= cut; }),
              audio.end());
  for (AudioClip& a : audio) {
    // Compared as doubles first: a cut far beyond the sound would not fit a size_t.
    const double keep = std::floor((cut - a.begin) * a.sample_rate);
    if (keep < static_cast<double>(a.samples.size())) a.samples.resize(static_cast<std::size_t>(keep));
  }
  std::pair<std::size_t, std::string> removed{0, ""};
  std::vector<ScheduledBehaviour>& behaviours = doc.behaviours;
  behaviours.erase(std::remove_if(behaviours.begin(), behaviours.end(),
                                  [&](const ScheduledBehaviour& b) {
                                    if (b.start < cut) return false;
                                    if (removed.first++ == 0) removed.second = b.block + ":" + b.id;
                                    return true;
                                  }),
                   behaviours.end());
  for (ScheduledBehaviour& b : behaviours) b.end = std::min(b.end, cut);
  doc.marks.erase(
      std::remove_if(doc.marks.begin(), doc.marks.end(), [&](const ScheduledMark& m) { return m.time >= cut; }),
      doc.marks.end());
  return removed;
}

template <class T>
void append(std::vector<T>& to, std::vector<T>&& from) {
  to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

template <class T>
void add_new(std::vector<T>& to, const std::vector<T>& from) {
  for (const T& x : from)
    if (std::find(to.begin(), to.end(), x) == to.end()) to.push_back(x);
}

class Sequence {
 public:
  Sequence(const std::string& list_name, const ReaderOptions& options) : list_name_(list_name), options_(options) {}

  Status add(const ListedDocument& listed) {
    if (listed.at) {
      if (*listed.at < earlier_.arrival)
        return make_error(codes::bml::blocks_out_of_order, listed.at_where,
                          "at " + seconds_text(*listed.at) + " is before the block listed before it (sent at " +
                              seconds_text(earlier_.arrival) + "): blocks are listed in the order they are sent");
      earlier_.arrival = *listed.at;
    }
    Result<std::string> path = resolve_include(listed.name, list_name_, options_.includes, listed.where);
    if (!path) return path.error();
    Result<std::string> text = read_file_bytes(*path, options_.limits);
    if (!text) {
      Diagnostic d = text.error();
      d.message = "'" + listed.name + "': " + d.message;
      d.where = listed.where;
      return d;
    }
    if (const Status depth = xml::check_element_depth(*text, *path); !depth) return depth.error();
    Result<xml::XmlDocument> doc = xml::XmlDocument::parse(*text, *path, xml::BlankText{false, {"text", "speech"}});
    if (!doc) return doc.error();
    ReaderOptions options = options_;
    options.limits.max_runs = options_.limits.max_runs - counted_;
    Result<BmlDocument> block = read_sequenced_block(*doc, options, earlier_);
    if (!block) return block.error();
    counted_ += static_cast<std::int64_t>(block->behaviours.size()) + 1;
    if (Status ids = check_block_id(*doc, *block); !ids) return ids.error();
    if (block->compositions.front() == "REPLACE") {
      const auto [removed, first] = cut_at(out_, block->block_starts.front());
      if (removed > 0) {
        Diagnostic w =
            doc->warning(doc->root(), "composition",
                         "this REPLACE block, sent at " + seconds_text(block->block_starts.front()) + ", removes " +
                             std::to_string(removed) +
                             " behaviour(s) of earlier blocks that had not started (the first: " + first + ")");
        w.code = codes::bml::replaced.name;
        out_.warnings.push_back(std::move(w));
      }
    }
    merge(std::move(*block));
    earlier_.end = 0;
    for (const ScheduledBehaviour& b : out_.behaviours) earlier_.end = std::max(earlier_.end, b.end);
    return ok_status();
  }

  BmlDocument finish() {
    out_.timeline.explicit_end = earlier_.end;
    std::string dialects;
    for (const std::string& d : dialects_) dialects += (dialects.empty() ? "" : ", ") + d;
    out_.dialect = dialects;
    return std::move(out_);
  }

 private:
  const std::string& list_name_;
  const ReaderOptions& options_;
  EarlierBlocks earlier_;
  BmlDocument out_;
  std::vector<std::string> dialects_;
  std::int64_t counted_ = 0;

  // Block ids name blocks in references: BML 1.0 asks each to be unique; Greta's planners reuse
  // them (references then name the first), said once.
  Status check_block_id(const xml::XmlDocument& doc, const BmlDocument& block) {
    const std::string& id = block.blocks.front();
    if (id.empty() || std::find(out_.blocks.begin(), out_.blocks.end(), id) == out_.blocks.end()) return ok_status();
    if (block.dialect == "BML 1.0")
      return doc.error(
          codes::bml::duplicate_block_id_error, doc.root(), "id",
          "a second block with id '" + id + "' in this sequence (BML 1.0 asks every block's id to be unique)");
    Diagnostic w = doc.warning(doc.root(), "id",
                               "a second block with id '" + id + "' in this sequence: references name the first");
    w.code = codes::bml::duplicate_block_id.name;
    out_.warnings.push_back(std::move(w));
    return ok_status();
  }

  void merge(BmlDocument&& block) {
    add_new(dialects_, {block.dialect});
    append(out_.timeline.clips, std::move(block.timeline.clips));
    append(out_.timeline.audio, std::move(block.timeline.audio));
    out_.timeline.end_source = block.timeline.end_source;
    append(out_.blocks, std::move(block.blocks));
    append(out_.characters, std::move(block.characters));
    append(out_.behaviours, std::move(block.behaviours));
    append(out_.marks, std::move(block.marks));
    add_new(out_.languages, block.languages);
    append(out_.recordings, std::move(block.recordings));
    append(out_.warnings, std::move(block.warnings));
    append(out_.compositions, std::move(block.compositions));
    append(out_.block_starts, std::move(block.block_starts));
  }
};

}  // namespace

Result<BmlDocument> read_bml_sequence(std::string_view list, const std::string& list_name,
                                      const ReaderOptions& options) {
  Result<std::vector<ListedDocument>> listed = parse_list(list, list_name, options.limits.max_runs);
  if (!listed) return listed.error();
  Sequence sequence(list_name, options);
  for (const ListedDocument& d : *listed)
    if (Status added = sequence.add(d); !added) return added.error();
  return sequence.finish();
}

Result<BmlDocument> load_bml_sequence(const std::string& path, const ReaderOptions& options) {
  Result<std::string> text = read_file_bytes(path, options.limits);
  if (!text) return text.error();
  return read_bml_sequence(*text, path, options);
}

}  // namespace fapc::bml

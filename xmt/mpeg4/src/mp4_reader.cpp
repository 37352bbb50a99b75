// The MP4 reader: the box tree down to the sample tables, then each track's samples resolved to
// file offsets, decode times and sync flags, every one checked to lie inside the file.
#include "fapc/mpeg4/mp4_reader.hpp"
#include <optional>

#include <algorithm>

#include "fapc/mpeg4/codes.hpp"
#include "mp4_box_reader.hpp"

namespace fapc::mpeg4 {

namespace {

// The raw tables of one trak, before samples are resolved.
struct SampleTables {
  std::uint64_t stbl_offset = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stts;  // (count, duration)
  std::optional<std::vector<std::uint32_t>> stss;
  struct Run {
    std::uint32_t first_chunk, samples_per_chunk;
  };
  std::vector<Run> stsc;
  std::vector<std::uint32_t> sizes;
  std::vector<std::uint64_t> chunks;
  bool have_stsz = false, have_stco = false, have_stts = false, have_stsc = false;
  // Where each table box starts, so errors found while resolving samples point at their table.
  std::uint64_t stts_at = 0, stss_at = 0, stsc_at = 0, stsz_at = 0, stco_at = 0;
};

class Mp4Parser {
 public:
  explicit Mp4Parser(Mp4File& out) : out_(out), file_(out.file) {}

  Status top() {
    auto boxes = read_boxes(ByteReader(out_.data.data(), out_.data.size()), file_);
    if (!boxes) return boxes.error();
    bool have_moov = false;
    for (Box& box : *boxes) {
      if (box.type == "ftyp") {
        if (Status s = ftyp(box); !s) return s;
      } else if (box.type == "moov") {
        if (have_moov) return error(codes::mp4::second_moov, box.offset, "second 'moov' box");
        have_moov = true;
        if (Status s = moov(box); !s) return s;
      } else if (box.type == "moof") {
        warn(box.offset, "movie fragment ('moof') ignored: fapc reads only the samples described in 'moov'");
      }
    }
    if (!have_moov) return error(codes::mp4::no_moov, 0, "no 'moov' box: not an MP4 file, or one without a movie");
    return ok_status();
  }

 private:
  Status ftyp(Box& box) {
    ByteReader& in = box.body;
    out_.major_brand = fourcc(in);
    in.u32();  // minor version
    while (in.remaining() >= 4) out_.compatible_brands.push_back(fourcc(in));
    if (in.failed()) return error(codes::mp4::box_truncated, box.offset, "'ftyp' box shorter than 8 bytes");
    return ok_status();
  }

  Status moov(Box& box) {
    auto boxes = read_boxes(box.body, file_);
    if (!boxes) return boxes.error();
    bool have_mvhd = false;
    for (Box& child : *boxes) {
      if (child.type == "mvhd") {
        have_mvhd = true;
        ByteReader& in = child.body;
        const std::uint32_t version = in.u8();
        in.u24();
        in.skip(version == 1 ? 16 : 8);
        out_.timescale = in.u32();
        out_.duration = version == 1 ? in.u64() : in.u32();
        if (in.failed()) return error(codes::mp4::box_truncated, child.offset, "'mvhd' box cut short");
      } else if (child.type == "iods") {
        ByteReader& in = child.body;
        in.u32();  // version, flags
        if (in.failed()) return error(codes::mp4::box_truncated, child.offset, "'iods' box cut short");
        auto iod = decode_initial_object_descriptor(in.bytes(in.remaining()), child.offset + 12, file_);
        if (!iod) return iod.error();
        out_.iod = std::move(*iod);
      } else if (child.type == "trak") {
        if (Status s = trak(child); !s) return s;
      }
    }
    if (!have_mvhd) return error(codes::mp4::missing_box, box.offset, "'moov' box without 'mvhd'");
    return ok_status();
  }

  Status trak(Box& box) {
    Mp4Track track;
    track.box_offset = box.offset;
    SampleTables tables;
    std::optional<std::uint64_t> edts_at;
    auto boxes = read_boxes(box.body, file_);
    if (!boxes) return boxes.error();
    bool have_tkhd = false, have_mdia = false;
    for (Box& child : *boxes) {
      if (child.type == "tkhd") {
        have_tkhd = true;
        ByteReader& in = child.body;
        const std::uint32_t version = in.u8();
        in.u24();
        in.skip(version == 1 ? 16 : 8);
        track.id = in.u32();
        if (in.failed()) return error(codes::mp4::box_truncated, child.offset, "'tkhd' box cut short");
      } else if (child.type == "tref") {
        auto refs = read_boxes(child.body, file_);
        if (!refs) return refs.error();
        for (Box& ref : *refs)
          if (ref.type == "mpod")
            while (ref.body.remaining() >= 4) track.mpod.push_back(ref.body.u32());
      } else if (child.type == "edts") {
        edts_at = child.offset;
        if (Status s = edts(child, track); !s) return s;
      } else if (child.type == "mdia") {
        have_mdia = true;
        if (Status s = mdia(child, track, tables); !s) return s;
      }
    }
    if (!have_tkhd) return error(codes::mp4::missing_box, box.offset, "'trak' box without 'tkhd'");
    if (!have_mdia) return error(codes::mp4::missing_box, box.offset, "'trak' box without 'mdia'");
    if (Status s = resolve_samples(track, tables); !s) return s;
    // Only the voice's edit list is applied (read_audio_track); other tracks' times are the
    // sample table's.
    if (edts_at && track.handler != "soun")
      warn(*edts_at, "edit list ('edts') ignored: times are read as the sample table gives them");
    out_.tracks.push_back(std::move(track));
    return ok_status();
  }

  // The edit list's entries; checked against its box before anything is allocated.
  Status edts(Box& box, Mp4Track& track) {
    auto boxes = read_boxes(box.body, file_);
    if (!boxes) return boxes.error();
    for (Box& child : *boxes) {
      if (child.type != "elst") continue;
      ByteReader& in = child.body;
      const std::uint32_t version = in.u8();
      in.u24();
      const std::uint32_t count = in.u32();
      if (in.failed()) return error(codes::mp4::box_truncated, child.offset, "'elst' box cut short");
      if (version > 1)
        return error(codes::mp4::bad_edit_list, child.offset,
                     "'elst' version " + std::to_string(version) + " is unknown");
      const std::size_t entry = version == 1 ? 20 : 12;
      if (count > in.remaining() / entry)
        return error(codes::mp4::bad_edit_list, child.offset,
                     "'elst' claims " + std::to_string(count) + " entries; its box holds " +
                         std::to_string(in.remaining() / entry));
      track.edits_offset = child.offset;
      for (std::uint32_t i = 0; i < count; ++i) {
        Mp4Edit e;
        if (version == 1) {
          e.duration = in.u64();
          e.media_time = static_cast<std::int64_t>(in.u64());
        } else {
          e.duration = in.u32();
          e.media_time = static_cast<std::int32_t>(in.u32());
        }
        const std::uint32_t rate = in.u32();
        if (rate != 0x00010000 && e.media_time != -1)
          return error(codes::mp4::bad_edit_list, child.offset,
                       "'elst' entry " + std::to_string(i + 1) + " plays at a rate other than 1");
        track.edits.push_back(e);
      }
    }
    return ok_status();
  }

  Status mdia(Box& box, Mp4Track& track, SampleTables& tables) {
    auto boxes = read_boxes(box.body, file_);
    if (!boxes) return boxes.error();
    bool have_mdhd = false, have_stbl = false;
    for (Box& child : *boxes) {
      if (child.type == "mdhd") {
        have_mdhd = true;
        ByteReader& in = child.body;
        const std::uint32_t version = in.u8();
        in.u24();
        in.skip(version == 1 ? 16 : 8);
        track.timescale = in.u32();
        track.duration = version == 1 ? in.u64() : in.u32();
        if (in.failed()) return error(codes::mp4::box_truncated, child.offset, "'mdhd' box cut short");
        if (track.timescale == 0) return error(codes::mp4::bad_timescale, child.offset, "'mdhd' timescale is 0");
      } else if (child.type == "hdlr") {
        ByteReader& in = child.body;
        in.skip(8);  // version, flags, pre_defined
        track.handler = fourcc(in);
        if (in.failed()) return error(codes::mp4::box_truncated, child.offset, "'hdlr' box cut short");
      } else if (child.type == "minf") {
        auto minf = read_boxes(child.body, file_);
        if (!minf) return minf.error();
        for (Box& m : *minf)
          if (m.type == "stbl") {
            have_stbl = true;
            if (Status s = stbl(m, track, tables); !s) return s;
          }
      }
    }
    if (!have_mdhd) return error(codes::mp4::missing_box, box.offset, "'mdia' box without 'mdhd'");
    if (!have_stbl) return error(codes::mp4::missing_box, box.offset, "'mdia' box without 'minf/stbl'");
    return ok_status();
  }

  Status stbl(Box& box, Mp4Track& track, SampleTables& t) {
    t.stbl_offset = box.offset;
    auto boxes = read_boxes(box.body, file_);
    if (!boxes) return boxes.error();
    for (Box& child : *boxes) {
      ByteReader& in = child.body;
      const std::string& type = child.type;
      if (type != "stsd" && type != "stts" && type != "stss" && type != "stsc" && type != "stsz" && type != "stco" &&
          type != "co64" && type != "stz2")
        continue;
      in.u32();  // version, flags
      if (type == "stz2")
        return error(codes::mp4::compact_sizes, child.offset, "compact sample sizes ('stz2') are not supported");
      if (type == "stsd") {
        if (Status s = stsd(child, track); !s) return s;
        continue;
      }
      const std::uint32_t fixed = type == "stsz" ? in.u32() : 0;  // stsz: one size for all, or 0
      std::uint32_t count = in.u32();
      if (type == "stsz") {
        t.have_stsz = true;
        if (fixed != 0) {
          // One size for all: the count is bounded by what the file can hold, not by this box.
          if (count > out_.data.size())
            return error(codes::mp4::bad_sample_table, child.offset,
                         "'stsz' sample count " + std::to_string(count) + " exceeds the file size");
          t.sizes.assign(count, fixed);
          count = 0;
        }
      }
      const std::size_t entry = type == "stts" ? 8 : type == "stsc" ? 12 : type == "co64" ? 8 : 4;
      if (in.failed() || count > in.remaining() / entry)
        return error(codes::mp4::bad_sample_table, child.offset,
                     "'" + type + "' box holds fewer entries than its count (" + std::to_string(count) + ")");
      for (std::uint32_t i = 0; i < count; ++i) {
        if (type == "stts") {
          const std::uint32_t n = in.u32();
          t.stts.emplace_back(n, in.u32());
        } else if (type == "stss") {
          if (!t.stss) t.stss.emplace();
          t.stss->push_back(in.u32());
        } else if (type == "stsc") {
          const std::uint32_t first = in.u32(), per_chunk = in.u32();
          in.u32();  // sample description index
          if (first == 0 || (!t.stsc.empty() && first <= t.stsc.back().first_chunk))
            return error(codes::mp4::bad_sample_table, child.offset,
                         "'stsc' entry " + std::to_string(i + 1) + " has first chunk " + std::to_string(first) +
                             ", not after the previous entry");
          t.stsc.push_back({first, per_chunk});
        } else if (type == "stsz") {
          t.sizes.push_back(in.u32());
        } else {
          t.chunks.push_back(type == "co64" ? in.u64() : in.u32());
        }
      }
      if (type == "stss" && !t.stss) t.stss.emplace();
      (type == "stts"   ? t.stts_at
       : type == "stss" ? t.stss_at
       : type == "stsc" ? t.stsc_at
       : type == "stsz" ? t.stsz_at
                        : t.stco_at) = child.offset;
      t.have_stts |= type == "stts";
      t.have_stsc |= type == "stsc";
      t.have_stco |= type == "stco" || type == "co64";
    }
    return ok_status();
  }

  Status stsd(Box& box, Mp4Track& track) {
    ByteReader& in = box.body;
    const std::uint32_t count = in.u32();
    if (in.failed() || count == 0)
      return error(codes::mp4::missing_box, box.offset, "'stsd' box without a sample entry");
    if (count > 1) warn(box.offset, "only the first of " + std::to_string(count) + " sample entries is read");
    auto entries = read_boxes(ByteReader(in.here(), in.remaining(), in.offset()), file_);
    if (!entries) return entries.error();
    if (entries->empty()) return error(codes::mp4::missing_box, box.offset, "'stsd' box without a sample entry");
    Box& entry = entries->front();
    track.sample_entry = entry.type;
    // Bytes before the child boxes: SampleEntry (8), plus VisualSampleEntry (70) or
    // AudioSampleEntry (20) fields.
    std::size_t fixed = 0;
    if (entry.type == "mp4s")
      fixed = 8;
    else if (entry.type == "mp4v")
      fixed = 78;
    else if (entry.type == "mp4a")
      fixed = 28;
    else
      return ok_status();  // not an MPEG-4 systems sample entry: no ES descriptor to read
    ByteReader& e = entry.body;
    if (e.remaining() < fixed)
      return error(codes::mp4::box_truncated, entry.offset, "sample entry '" + entry.type + "' cut short");
    e.skip(fixed);
    auto children = read_boxes(ByteReader(e.here(), e.remaining(), e.offset()), file_);
    if (!children) return children.error();
    for (Box& child : *children) {
      if (child.type != "esds") continue;
      child.body.u32();  // version, flags
      if (child.body.failed()) return error(codes::mp4::box_truncated, child.offset, "'esds' box cut short");
      track.es_offset = child.body.offset();
      auto es = decode_es_descriptor(child.body.bytes(child.body.remaining()), track.es_offset, file_);
      if (!es) return es.error();
      track.es = std::move(*es);
    }
    if (!track.es)
      return error(codes::mp4::missing_box, entry.offset, "sample entry '" + entry.type + "' without an 'esds' box");
    return ok_status();
  }

  Status resolve_samples(Mp4Track& track, const SampleTables& t) {
    const std::uint64_t at = t.stbl_offset;
    const std::string id = "track " + std::to_string(track.id);
    if (!t.have_stsz || !t.have_stco || !t.have_stts || !t.have_stsc)
      return error(codes::mp4::missing_box, at, id + ": sample table lacks one of 'stts', 'stsc', 'stsz', 'stco'");
    const std::size_t n = t.sizes.size();
    track.samples.resize(n);
    // Decoding times from stts runs; the counts must add up to the sample count exactly.
    std::size_t i = 0;
    std::uint64_t time = 0;
    for (const auto& [count, duration] : t.stts) {
      if (count > n - i)
        return error(codes::mp4::bad_sample_table, t.stts_at,
                     id + ": 'stts' describes more samples than 'stsz' (" + std::to_string(n) + ")");
      for (std::uint32_t k = 0; k < count; ++k, ++i) {
        track.samples[i].decode_time = time;
        track.samples[i].duration = duration;
        time += duration;
      }
    }
    if (i != n)
      return error(codes::mp4::bad_sample_table, t.stts_at,
                   id + ": 'stts' describes " + std::to_string(i) + " samples, 'stsz' " + std::to_string(n));
    if (t.stss) {
      for (Mp4Sample& s : track.samples) s.sync = false;
      for (std::uint32_t number : *t.stss) {
        if (number == 0 || number > n)
          return error(codes::mp4::bad_sample_table, t.stss_at,
                       id + ": 'stss' names sample " + std::to_string(number) + " of " + std::to_string(n));
        track.samples[number - 1].sync = true;
      }
    }
    // Chunks: stsc runs give samples per chunk; samples in a chunk follow each other.
    i = 0;
    std::size_t run = 0;  // the stsc entry in force (entries ascend by first chunk)
    for (std::size_t chunk = 0; chunk < t.chunks.size() && i < n; ++chunk) {
      while (run + 1 < t.stsc.size() && t.stsc[run + 1].first_chunk <= chunk + 1) ++run;
      const std::uint32_t per_chunk =
          !t.stsc.empty() && t.stsc[run].first_chunk <= chunk + 1 ? t.stsc[run].samples_per_chunk : 0;
      std::uint64_t offset = t.chunks[chunk];
      for (std::uint32_t k = 0; k < per_chunk && i < n; ++k, ++i) {
        Mp4Sample& s = track.samples[i];
        s.offset = offset;
        s.size = t.sizes[i];
        if (offset > out_.data.size() || s.size > out_.data.size() - offset)
          return error(codes::mp4::bad_sample_table, t.stco_at,
                       id + ": sample " + std::to_string(i + 1) + " (" + std::to_string(s.size) + " bytes at offset " +
                           std::to_string(offset) + ") lies outside the file");
        offset += s.size;
      }
    }
    if (i != n)
      return error(codes::mp4::bad_sample_table, t.stsc_at,
                   id + ": 'stsc' and 'stco' place " + std::to_string(i) + " of " + std::to_string(n) + " samples");
    return ok_status();
  }

  static std::string fourcc(ByteReader& in) {
    std::string s;
    for (int k = 0; k < 4; ++k) {
      const auto c = static_cast<char>(in.u8());
      s += (c >= 0x20 && c < 0x7F) ? c : '?';
    }
    return s;
  }
  Diagnostic error(ErrorCode code, std::uint64_t offset, const std::string& message) const {
    return box_error(code, file_, offset, message);
  }
  void warn(std::uint64_t offset, const std::string& message) {
    out_.warnings.push_back(
        make_warning(codes::mp4::ignored, Location::binary(file_, static_cast<std::int64_t>(offset)), message));
  }

  Mp4File& out_;
  const std::string& file_;
};

}  // namespace

const Mp4Track* Mp4File::track(std::uint32_t id) const {
  for (const Mp4Track& t : tracks)
    if (t.id == id) return &t;
  return nullptr;
}

Bytes Mp4File::sample_bytes(const Mp4Sample& s) const {
  const auto begin = data.begin() + static_cast<std::ptrdiff_t>(s.offset);
  return Bytes(begin, begin + s.size);
}

Result<Mp4File> read_mp4(Bytes data, const std::string& file) {
  Mp4File out;
  out.file = file;
  out.data = std::move(data);
  Mp4Parser parser(out);
  if (Status s = parser.top(); !s) return s.error();
  return out;
}

}  // namespace fapc::mpeg4

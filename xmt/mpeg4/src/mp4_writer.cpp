// The MP4 writer: plans three tracks (scene, object descriptors, FBA), lays out moov before mdat
// with one chunk per track, and writes the boxes. Times and creation dates are fixed (0) so the
// same input always gives the same bytes. The plans hold views of the samples, not copies, and
// the file goes out in pieces: moov is some 12 bytes a sample, mdat is the samples themselves.
#include "fapc/mpeg4/mp4_writer.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "box_writer.hpp"
#include "fapc/mpeg4/codes.hpp"
#include "fapc/mpeg4/object_descriptors.hpp"
#include "fapc/mpeg4/scene.hpp"

namespace fapc::mpeg4 {

namespace {

using Piece = std::span<const std::uint8_t>;

std::uint64_t to_movie_time(std::uint64_t ticks, std::uint32_t timescale) {
  return (ticks * kSystemsTimescale + timescale / 2) / timescale;
}

// One edit of an edit list (14496-12 §8.6.6), times in the movie's timescale and the media's.
struct Edit {
  std::uint32_t duration = 0;    // movie timescale
  std::int32_t media_time = -1;  // -1: an empty edit (nothing plays)
};

struct TrackPlan {
  std::uint32_t id = 0;
  std::string_view handler;       // 'sdsm', 'odsm', 'vide', 'soun'
  std::string_view handler_name;  // shown by tools
  std::uint32_t timescale = kSystemsTimescale;
  EsDescriptor es;
  std::vector<Piece> samples;  // views: the bytes belong to the caller or to write_mp4
  std::vector<std::uint32_t> durations;
  std::vector<std::uint32_t> sync;  // 1-based numbers of sync samples
  bool all_sync = true;             // then no stss box: every sample is a sync sample
  std::vector<std::uint32_t> mpod;  // track references of an OD track
  std::vector<Edit> edits;          // an audio track's delay and priming; none for the others
  int channels = 1;                 // audio
  bool visual() const { return handler == "vide"; }
  bool audio() const { return handler == "soun"; }
  // The track's length on the movie's clock: its edits when it has them.
  std::uint64_t movie_duration() const {
    if (edits.empty()) return to_movie_time(duration(), timescale);
    std::uint64_t total = 0;
    for (const Edit& e : edits) total += e.duration;
    return total;
  }
  std::uint64_t duration() const {
    std::uint64_t total = 0;
    for (std::uint32_t d : durations) total += d;
    return total;
  }
};

// The average bit rate over the whole track, and the most bits in any one-second window that
// starts at a sample (14496-1 §7.2.6.6 asks for the maximum over any one-second period).
void set_bitrates(TrackPlan& t) {
  const std::size_t n = t.samples.size();
  std::vector<std::uint64_t> starts(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) starts[i + 1] = starts[i] + t.durations[i];
  std::uint64_t total = 0, window = 0, best = 0;
  std::uint32_t largest = 0;
  std::size_t end = 0;  // the window is samples [first, end)
  for (std::size_t first = 0; first < n; ++first) {
    while (end < n && starts[end] < starts[first] + t.timescale) window += t.samples[end++].size();
    best = std::max(best, window);
    window -= t.samples[first].size();
    total += t.samples[first].size();
    largest = std::max(largest, static_cast<std::uint32_t>(t.samples[first].size()));
  }
  const auto clamp32 = [](std::uint64_t v) {
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(v, std::numeric_limits<std::uint32_t>::max()));
  };
  t.es.config.buffer_size = std::min<std::uint32_t>(largest, 0xFFFFFF);
  t.es.config.avg_bitrate = clamp32(total * 8 * t.timescale / std::max<std::uint64_t>(starts[n], 1));
  // A track shorter than a second still has all its bits within one second.
  t.es.config.max_bitrate = std::max(clamp32(best * 8), t.es.config.avg_bitrate);
}

void write_matrix(ByteWriter& out) {
  for (std::uint32_t v : {0x00010000U, 0U, 0U, 0U, 0x00010000U, 0U, 0U, 0U, 0x40000000U}) out.u32(v);
}

void write_sample_entry(BoxWriter& box, const TrackPlan& t) {
  ByteWriter& out = box.out();
  box.open(t.visual() ? "mp4v" : t.audio() ? "mp4a" : "mp4s");
  out.zeros(6);
  out.u16(1);       // data_reference_index
  if (t.audio()) {  // AudioSampleEntry (14496-14 §5.6): the decoder configuration is in esds
    out.zeros(8);   // reserved
    out.u16(static_cast<std::uint32_t>(t.channels));
    out.u16(16);  // samplesize
    out.u16(0);   // pre_defined
    out.u16(0);   // reserved
    // The rate as 16.16 fixed point; a rate past 16 bits is given by the media timescale alone.
    out.u32(t.timescale < 65536 ? t.timescale << 16 : 0);
  }
  if (t.visual()) {
    out.zeros(16);        // pre_defined, reserved, pre_defined[3]
    out.u16(0);           // width: an FBA stream has no picture size
    out.u16(0);           // height
    out.u32(0x00480000);  // 72 dpi
    out.u32(0x00480000);
    out.u32(0);
    out.u16(1);     // frame_count
    out.zeros(32);  // compressorname: empty
    out.u16(0x0018);
    out.u16(0xFFFF);  // pre_defined = -1
  }
  box.open_full("esds", 0, 0);
  out.bytes(encode_es_descriptor(t.es));
  box.close();
  box.close();
}

void write_sample_table(BoxWriter& box, const TrackPlan& t, std::uint64_t chunk_offset) {
  ByteWriter& out = box.out();
  const auto count = static_cast<std::uint32_t>(t.samples.size());
  box.open("stbl");
  box.open_full("stsd", 0, 0);
  out.u32(1);
  write_sample_entry(box, t);
  box.close();
  // stts: runs of equal durations.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;
  for (std::uint32_t d : t.durations) {
    if (!runs.empty() && runs.back().second == d)
      ++runs.back().first;
    else
      runs.emplace_back(1, d);
  }
  box.open_full("stts", 0, 0);
  out.u32(static_cast<std::uint32_t>(runs.size()));
  for (const auto& [n, d] : runs) {
    out.u32(n);
    out.u32(d);
  }
  box.close();
  if (!t.all_sync) {
    box.open_full("stss", 0, 0);
    out.u32(static_cast<std::uint32_t>(t.sync.size()));
    for (std::uint32_t s : t.sync) out.u32(s);
    box.close();
  }
  box.open_full("stsc", 0, 0);  // one chunk holding every sample
  out.u32(1);
  out.u32(1);
  out.u32(count);
  out.u32(1);
  box.close();
  box.open_full("stsz", 0, 0);
  out.u32(0);
  out.u32(count);
  for (const Piece& s : t.samples) out.u32(static_cast<std::uint32_t>(s.size()));
  box.close();
  box.open_full("stco", 0, 0);
  out.u32(1);
  out.u32(static_cast<std::uint32_t>(chunk_offset));
  box.close();
  box.close();
}

void write_track(BoxWriter& box, const TrackPlan& t, std::uint64_t chunk_offset) {
  ByteWriter& out = box.out();
  box.open("trak");
  box.open_full("tkhd", 0, 0x000003);  // enabled, in movie
  out.u32(0);                          // creation_time
  out.u32(0);                          // modification_time
  out.u32(t.id);
  out.u32(0);
  out.u32(static_cast<std::uint32_t>(t.movie_duration()));
  out.zeros(8);
  out.u16(0);                       // layer
  out.u16(0);                       // alternate_group
  out.u16(t.audio() ? 0x0100 : 0);  // volume: 1.0 for sound
  out.u16(0);
  write_matrix(out);
  out.u32(0);  // width
  out.u32(0);  // height
  box.close();
  if (!t.edits.empty()) {
    box.open("edts");
    box.open_full("elst", 0, 0);
    out.u32(static_cast<std::uint32_t>(t.edits.size()));
    for (const Edit& e : t.edits) {
      out.u32(e.duration);
      out.u32(static_cast<std::uint32_t>(e.media_time));
      out.u16(1);  // media_rate_integer
      out.u16(0);  // media_rate_fraction
    }
    box.close();
    box.close();
  }
  if (!t.mpod.empty()) {
    box.open("tref");
    box.open("mpod");
    for (std::uint32_t id : t.mpod) out.u32(id);
    box.close();
    box.close();
  }
  box.open("mdia");
  box.open_full("mdhd", 0, 0);
  out.u32(0);
  out.u32(0);
  out.u32(t.timescale);
  out.u32(static_cast<std::uint32_t>(t.duration()));
  out.u16(0x55C4);  // language "und", packed 5 bits per letter
  out.u16(0);
  box.close();
  box.open_full("hdlr", 0, 0);
  out.u32(0);
  out.fourcc(t.handler);
  out.zeros(12);
  for (char c : t.handler_name) out.u8(static_cast<std::uint8_t>(c));
  out.u8(0);
  box.close();
  box.open("minf");
  if (t.visual()) {
    box.open_full("vmhd", 0, 1);
    out.zeros(8);  // graphicsmode, opcolor
  } else if (t.audio()) {
    box.open_full("smhd", 0, 0);
    out.u16(0);  // balance: centre
    out.u16(0);
  } else {
    box.open_full("nmhd", 0, 0);
  }
  box.close();
  box.open("dinf");
  box.open_full("dref", 0, 0);
  out.u32(1);
  box.open_full("url ", 0, 1);  // the media is in this file
  box.close();
  box.close();
  box.close();
  write_sample_table(box, t, chunk_offset);
  box.close();  // minf
  box.close();  // mdia
  box.close();  // trak
}

Bytes write_moov(const std::vector<TrackPlan>& tracks, const std::vector<std::uint64_t>& offsets,
                 const ProfileLevels& profiles) {
  BoxWriter box;
  ByteWriter& out = box.out();
  std::uint64_t movie_duration = 0;
  for (const TrackPlan& t : tracks) movie_duration = std::max(movie_duration, t.movie_duration());
  box.open("moov");
  box.open_full("mvhd", 0, 0);
  out.u32(0);
  out.u32(0);
  out.u32(kSystemsTimescale);
  out.u32(static_cast<std::uint32_t>(movie_duration));
  out.u32(0x00010000);  // rate 1.0
  out.u16(0x0100);      // volume 1.0
  out.zeros(10);
  write_matrix(out);
  out.zeros(24);
  out.u32(tracks.back().id + 1);  // next_track_ID
  box.close();
  box.open_full("iods", 0, 0);
  out.bytes(encode_initial_object_descriptor({1, profiles, {kSceneTrackId, kOdTrackId}}));
  box.close();
  for (std::size_t i = 0; i < tracks.size(); ++i) write_track(box, tracks[i], offsets[i]);
  box.close();
  return box.out().take();
}

Bytes ftyp() {
  BoxWriter box;
  box.open("ftyp");
  box.out().fourcc("mp42");
  box.out().u32(0);
  for (std::string_view brand : {"mp42", "isom"}) box.out().fourcc(brand);
  box.close();
  return box.out().take();
}

TrackPlan system_track(std::uint32_t id, std::string_view handler, std::string_view name, std::uint8_t stream_type,
                       Piece sample, std::uint32_t duration) {
  TrackPlan t;
  t.id = id;
  t.handler = handler;
  t.handler_name = name;
  t.es.config.object_type = kSystemsV1Object;
  t.es.config.stream_type = stream_type;
  t.samples.push_back(sample);
  t.durations.push_back(duration);
  return t;
}

// The voice's track: one access unit per sample, every one lasting samples_per_unit; an edit list
// that delays it to its start on the face's clock and skips the encoder's priming.
TrackPlan audio_track_plan(const AudioTrackInput& audio) {
  TrackPlan t;
  t.id = kAudioTrackId;
  t.handler = "soun";
  t.handler_name = "fapc voice";
  t.timescale = audio.sample_rate;
  t.channels = audio.channels;
  t.es.config.object_type = kAudio14496_3Object;
  t.es.config.stream_type = kAudioStream;
  t.es.config.specific_info = audio.decoder_specific_info;
  t.samples.assign(audio.samples.begin(), audio.samples.end());
  t.durations.assign(audio.samples.size(), audio.samples_per_unit);
  if (audio.delay_ms > 0) t.edits.push_back({audio.delay_ms, -1});
  t.edits.push_back({static_cast<std::uint32_t>(to_movie_time(audio.length, audio.sample_rate)),
                     static_cast<std::int32_t>(audio.media_start)});
  set_bitrates(t);
  return t;
}

// Gathers small writes into pieces of about 1 MB for the sink.
class PieceOut {
 public:
  explicit PieceOut(const Mp4Sink& sink) : sink_(sink) {}
  Status put(Piece bytes) {
    buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
    return buffer_.size() >= (std::size_t{1} << 20) ? flush() : ok_status();
  }
  Status flush() {
    if (buffer_.empty()) return ok_status();
    Status status = sink_(buffer_);
    buffer_.clear();
    return status;
  }

 private:
  const Mp4Sink& sink_;
  Bytes buffer_;
};

}  // namespace

Result<Bytes> write_mp4(const FbaTrackInput& fba, const AudioTrackInput* audio) {
  Bytes file;
  const Status written = write_mp4(view_of(fba), audio, [&](Piece bytes) {
    file.insert(file.end(), bytes.begin(), bytes.end());
    return ok_status();
  });
  if (!written) return written.error();
  return file;
}

Status write_mp4(const FbaTrackView& fba, const AudioTrackInput* audio, const Mp4Sink& sink) {
  if (Status s = check_fba_track(fba); !s) return s.error();
  if (audio)
    if (Status s = check_audio_track(*audio); !s) return s.error();
  const std::uint8_t visual_level = *fba_profile_level(fba.decoder_specific_info);

  TrackPlan fba_track;
  fba_track.id = kFbaTrackId;
  fba_track.handler = "vide";
  fba_track.handler_name = "fapc FBA stream";
  fba_track.timescale = fba.timescale;
  fba_track.es.config.object_type = kVisual14496_2Object;
  fba_track.es.config.stream_type = kVisualStream;
  fba_track.es.config.specific_info = fba.decoder_specific_info;
  fba_track.all_sync = false;  // stss is always written: planes are intra or predicted
  fba_track.samples.reserve(fba.samples.size());
  fba_track.durations.reserve(fba.samples.size());
  for (const FbaSampleView& s : fba.samples) {
    fba_track.samples.push_back(s.bytes);
    fba_track.durations.push_back(s.duration);
    if (s.sync) fba_track.sync.push_back(static_cast<std::uint32_t>(fba_track.samples.size()));
  }
  set_bitrates(fba_track);

  // The scene and OD access units last the whole presentation.
  std::optional<TrackPlan> voice;
  if (audio) voice = audio_track_plan(*audio);
  const auto span = static_cast<std::uint32_t>(std::max<std::uint64_t>(
      {1, to_movie_time(fba_track.duration(), fba.timescale), voice ? voice->movie_duration() : 0}));
  const BifsConfig config;
  auto scene_au =
      encode_scene_replace(audio ? with_sound(face_scene(), kAudioObjectDescriptorId) : face_scene(), config);
  if (!scene_au) return scene_au.error();
  // One zero byte after the command frame. GPAC's BIFS decoder stops reading a node's field list
  // or an MFNode list early when the bits left lie in the last byte of the access unit (it counts
  // whole bytes left), and then fails on this scene; with the padding it decodes it. A decoder
  // that follows the syntax stops at the last command's continue flag and never reads the byte.
  scene_au->push_back(0);
  TrackPlan scene = system_track(kSceneTrackId, "sdsm", "fapc scene", kSceneDescriptionStream, *scene_au, span);
  scene.es.config.specific_info = encode_bifs_config(config);
  std::vector<ObjectDescriptor> ods = {{kFbaObjectDescriptorId, {1}}};
  if (audio) ods.push_back({kAudioObjectDescriptorId, {2}});
  const Bytes od_au = encode_object_descriptor_update(ods);
  TrackPlan od = system_track(kOdTrackId, "odsm", "fapc object descriptors", kObjectDescriptorStream, od_au, span);
  od.mpod = {kFbaTrackId};                      // ES_ID_Ref 1 is this first entry
  if (audio) od.mpod.push_back(kAudioTrackId);  // and 2 the second
  set_bitrates(scene);
  set_bitrates(od);

  std::vector<TrackPlan> tracks;
  tracks.push_back(std::move(scene));
  tracks.push_back(std::move(od));
  tracks.push_back(std::move(fba_track));
  if (voice) tracks.push_back(std::move(*voice));

  ProfileLevels profiles;
  profiles.od = 0x01;  // GPAC's value when an OD stream exists (docs/mp4-and-xmta.md section 6.4)
  profiles.visual = visual_level;
  if (audio) profiles.audio = aac_profile_level(audio->sample_rate);

  // moov's size does not depend on the offsets it holds, so lay out once with zeros.
  std::vector<std::uint64_t> offsets(tracks.size(), 0);
  const Bytes head = ftyp();
  const std::uint64_t mdat_start = head.size() + write_moov(tracks, offsets, profiles).size();
  std::uint64_t at = mdat_start + 8;  // after the mdat header
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    offsets[i] = at;
    for (const Piece& s : tracks[i].samples) at += s.size();
  }
  if (at > std::numeric_limits<std::uint32_t>::max())
    return make_error(codes::mp4::too_large, Location{},
                      "MP4 output would exceed 4 GiB; fapc writes 32-bit offsets only");

  PieceOut file(sink);
  ByteWriter mdat_header;
  mdat_header.u32(static_cast<std::uint32_t>(at - mdat_start));
  mdat_header.fourcc("mdat");
  if (Status s = file.put(head); !s) return s;
  if (Status s = file.put(write_moov(tracks, offsets, profiles)); !s) return s;
  if (Status s = file.put(mdat_header.data()); !s) return s;
  for (const TrackPlan& t : tracks)
    for (const Piece& s : t.samples)
      if (Status status = file.put(s); !status) return status;
  return file.flush();
}

}  // namespace fapc::mpeg4

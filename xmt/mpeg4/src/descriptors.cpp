// Object descriptor framework coding (14496-1 §7.2.6 and §7.2.2.3). Each descriptor is a tag, a
// size in 7-bit groups with a continuation bit, and its payload.
#include "fapc/mpeg4/object_descriptors.hpp"

#include <optional>

#include "byte_io.hpp"
#include "fapc/mpeg4/codes.hpp"

namespace fapc::mpeg4 {

namespace {

void put_descriptor(ByteWriter& out, std::uint8_t tag, const Bytes& payload) {
  out.u8(tag);
  // Shortest size form: 7 bits per byte, most significant group first.
  std::size_t groups = 1;
  while (groups < 4 && payload.size() >= (std::size_t{1} << (7 * groups))) ++groups;
  for (std::size_t g = groups; g-- > 0;) {
    const auto bits = static_cast<std::uint32_t>((payload.size() >> (7 * g)) & 0x7F);
    out.u8(g > 0 ? (0x80 | bits) : bits);
  }
  out.bytes(payload);
}

Bytes decoder_config_payload(const DecoderConfig& c) {
  ByteWriter out;
  out.u8(c.object_type);
  out.u8(static_cast<std::uint32_t>(c.stream_type << 2) | (c.up_stream ? 2U : 0U) | 1U);  // reserved 1
  out.u24(c.buffer_size);
  out.u32(c.max_bitrate);
  out.u32(c.avg_bitrate);
  if (!c.specific_info.empty()) put_descriptor(out, kDecoderSpecificInfoTag, c.specific_info);
  return out.take();
}

// Reading: a descriptor's tag, size and payload, bounded by its parent.
struct Descriptor {
  std::uint8_t tag = 0;
  std::uint64_t offset = 0;  // file offset of the tag byte
  ByteReader body{nullptr, 0};
};

class DescriptorParser {
 public:
  DescriptorParser(const std::string& file) : file_(file) {}

  // The next descriptor inside `in`, or an error naming where it went wrong.
  Result<Descriptor> next(ByteReader& in) {
    Descriptor d;
    d.offset = in.offset();
    d.tag = static_cast<std::uint8_t>(in.u8());
    std::size_t size = 0;
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t b = in.u8();
      size = (size << 7) | (b & 0x7F);
      if ((b & 0x80) == 0) break;
      if (i == 3) return error(codes::mp4::bad_descriptor, in.offset() - 1, "descriptor size longer than 4 bytes");
    }
    if (in.failed()) return error(codes::mp4::descriptor_truncated, in.failed_at(), "descriptor header cut short");
    if (size > in.remaining())
      return error(codes::mp4::bad_descriptor, d.offset,
                   "descriptor (tag 0x" + hex(d.tag) + ") of " + std::to_string(size) +
                       " bytes overruns its container (" + std::to_string(in.remaining()) + " bytes left)");
    d.body = ByteReader(in.here(), size, in.offset());
    in.skip(size);
    return d;
  }

  Diagnostic error(ErrorCode code, std::uint64_t offset, const std::string& message) const {
    return make_error(code, Location::binary(file_, static_cast<std::int64_t>(offset)), message);
  }
  Diagnostic cut_short(const ByteReader& in, const std::string& what) const {
    return error(codes::mp4::descriptor_truncated, in.failed_at(), what + " cut short");
  }

  static std::string hex(std::uint32_t v) {
    static const char* digits = "0123456789ABCDEF";
    return {digits[(v >> 4) & 15], digits[v & 15]};
  }

 private:
  const std::string& file_;
};

Result<DecoderConfig> read_decoder_config(DescriptorParser& p, ByteReader in) {
  DecoderConfig c;
  c.object_type = static_cast<std::uint8_t>(in.u8());
  const std::uint32_t type_byte = in.u8();
  c.stream_type = static_cast<std::uint8_t>(type_byte >> 2);
  c.up_stream = (type_byte & 2) != 0;
  c.buffer_size = in.u24();
  c.max_bitrate = in.u32();
  c.avg_bitrate = in.u32();
  if (in.failed()) return p.cut_short(in, "DecoderConfigDescriptor");
  while (in.remaining() > 0) {
    auto d = p.next(in);
    if (!d) return d.error();
    if (d->tag == kDecoderSpecificInfoTag) c.specific_info = d->body.bytes(d->body.remaining());
  }
  return c;
}

}  // namespace

Bytes encode_es_descriptor(const EsDescriptor& es) {
  ByteWriter payload;
  payload.u16(es.es_id);
  payload.u8(0);  // no stream dependence, no URL, no OCR stream, priority 0
  put_descriptor(payload, kDecoderConfigTag, decoder_config_payload(es.config));
  put_descriptor(payload, kSlConfigTag, Bytes{es.sl_predefined});
  ByteWriter out;
  put_descriptor(out, kEsDescriptorTag, payload.data());
  return out.take();
}

Bytes encode_initial_object_descriptor(const InitialObjectDescriptor& iod) {
  ByteWriter payload;
  // ObjectDescriptorID (10), URL_Flag 0, includeInlineProfileLevelFlag 0, reserved 1111.
  payload.u16(static_cast<std::uint32_t>(iod.od_id << 6) | 0x0F);
  const ProfileLevels& pl = iod.profiles;
  for (std::uint8_t level : {pl.od, pl.scene, pl.audio, pl.visual, pl.graphics}) payload.u8(level);
  for (std::uint32_t track : iod.es_id_incs) {
    ByteWriter inc;
    inc.u32(track);
    put_descriptor(payload, kEsIdIncTag, inc.data());
  }
  ByteWriter out;
  put_descriptor(out, kMp4IodTag, payload.data());
  return out.take();
}

Bytes encode_object_descriptor_update(const std::vector<ObjectDescriptor>& ods) {
  ByteWriter list;
  for (const ObjectDescriptor& od : ods) {
    ByteWriter payload;
    // ObjectDescriptorID (10), URL_Flag 0, reserved 11111.
    payload.u16(static_cast<std::uint32_t>(od.od_id << 6) | 0x1F);
    for (std::uint16_t ref : od.es_id_refs) {
      ByteWriter r;
      r.u16(ref);
      put_descriptor(payload, kEsIdRefTag, r.data());
    }
    put_descriptor(list, kMp4OdTag, payload.data());
  }
  ByteWriter out;
  put_descriptor(out, kObjectDescriptorUpdateTag, list.data());
  return out.take();
}

Result<EsDescriptor> decode_es_descriptor(const Bytes& bytes, std::uint64_t base, const std::string& file) {
  DescriptorParser p(file);
  ByteReader outer(bytes.data(), bytes.size(), base);
  auto d = p.next(outer);
  if (!d) return d.error();
  if (d->tag != kEsDescriptorTag)
    return p.error(codes::mp4::unexpected_descriptor, d->offset,
                   "expected an ES_Descriptor (tag 0x03), found tag 0x" + p.hex(d->tag));
  ByteReader& in = d->body;
  EsDescriptor es;
  es.es_id = static_cast<std::uint16_t>(in.u16());
  const std::uint32_t flags = in.u8();
  if (flags & 0x80) in.skip(2);        // dependsOn_ES_ID
  if (flags & 0x40) in.skip(in.u8());  // URL
  if (flags & 0x20) in.skip(2);        // OCR_ES_Id
  if (in.failed()) return p.cut_short(in, "ES_Descriptor");
  bool have_config = false;
  while (in.remaining() > 0) {
    auto sub = p.next(in);
    if (!sub) return sub.error();
    if (sub->tag == kDecoderConfigTag) {
      auto config = read_decoder_config(p, sub->body);
      if (!config) return config.error();
      es.config = std::move(*config);
      have_config = true;
    } else if (sub->tag == kSlConfigTag) {
      es.sl_predefined = static_cast<std::uint8_t>(sub->body.u8());
      if (sub->body.failed()) return p.cut_short(sub->body, "SLConfigDescriptor");
    }
  }
  if (!have_config)
    return p.error(codes::mp4::missing_descriptor, d->offset, "ES_Descriptor without a DecoderConfigDescriptor");
  return es;
}

Result<InitialObjectDescriptor> decode_initial_object_descriptor(const Bytes& bytes, std::uint64_t base,
                                                                 const std::string& file) {
  DescriptorParser p(file);
  ByteReader outer(bytes.data(), bytes.size(), base);
  auto d = p.next(outer);
  if (!d) return d.error();
  // 0x02 is the IOD form outside MP4 files; it has the same header.
  if (d->tag != kMp4IodTag && d->tag != 0x02)
    return p.error(codes::mp4::unexpected_descriptor, d->offset,
                   "expected an initial object descriptor (tag 0x10), found tag 0x" + p.hex(d->tag));
  ByteReader& in = d->body;
  InitialObjectDescriptor iod;
  const std::uint32_t head = in.u16();
  iod.od_id = static_cast<std::uint16_t>(head >> 6);
  if (head & 0x20) {
    in.skip(in.u8());  // a URL: the descriptor lives elsewhere; no profiles follow
  } else {
    ProfileLevels& pl = iod.profiles;
    for (std::uint8_t* level : {&pl.od, &pl.scene, &pl.audio, &pl.visual, &pl.graphics})
      *level = static_cast<std::uint8_t>(in.u8());
  }
  if (in.failed()) return p.cut_short(in, "initial object descriptor");
  while (in.remaining() > 0) {
    auto sub = p.next(in);
    if (!sub) return sub.error();
    if (sub->tag == kEsIdIncTag) {
      iod.es_id_incs.push_back(sub->body.u32());
      if (sub->body.failed()) return p.cut_short(sub->body, "ES_ID_Inc");
    }
  }
  return iod;
}

Result<std::vector<ObjectDescriptor>> decode_object_descriptor_updates(const Bytes& bytes, std::uint64_t base,
                                                                       const std::string& file) {
  DescriptorParser p(file);
  ByteReader commands(bytes.data(), bytes.size(), base);
  std::vector<ObjectDescriptor> ods;
  while (commands.remaining() > 0) {
    auto command = p.next(commands);
    if (!command) return command.error();
    if (command->tag != kObjectDescriptorUpdateTag)
      return p.error(
          codes::mp4::unexpected_descriptor, command->offset,
          "OD command with tag 0x" + p.hex(command->tag) + " is not an ObjectDescriptorUpdate; fapc reads only those");
    ByteReader& list = command->body;
    while (list.remaining() > 0) {
      auto d = p.next(list);
      if (!d) return d.error();
      if (d->tag != kMp4OdTag && d->tag != 0x01)
        return p.error(codes::mp4::unexpected_descriptor, d->offset,
                       "expected an object descriptor (tag 0x11), found tag 0x" + p.hex(d->tag));
      ByteReader& in = d->body;
      ObjectDescriptor od;
      const std::uint32_t head = in.u16();
      od.od_id = static_cast<std::uint16_t>(head >> 6);
      if (head & 0x20) in.skip(in.u8());
      if (in.failed()) return p.cut_short(in, "object descriptor");
      while (in.remaining() > 0) {
        auto sub = p.next(in);
        if (!sub) return sub.error();
        if (sub->tag == kEsIdRefTag) {
          od.es_id_refs.push_back(static_cast<std::uint16_t>(sub->body.u16()));
          if (sub->body.failed()) return p.cut_short(sub->body, "ES_ID_Ref");
        }
      }
      ods.push_back(std::move(od));
    }
  }
  return ods;
}

}  // namespace fapc::mpeg4

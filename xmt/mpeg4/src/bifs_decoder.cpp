// BIFS decoding, the inverse of bifs_encoder.cpp for the same node subset. Everything outside
// the subset (USE, PROTOs, ROUTEs, version 2 nodes, further commands) is an error naming the
// byte where it was found, so `fapc info` can say why it cannot show a scene.
#include <algorithm>
#include <bit>

#include "bifs_nodes.hpp"
#include "bit_io.hpp"
#include "fapc/mpeg4/bifs.hpp"
#include "fapc/mpeg4/codes.hpp"

namespace fapc::mpeg4 {

namespace {

using bifs::FieldKind;
using bifs::FieldSpec;
using bifs::Ndt;
using bifs::NodeSpec;

constexpr int kMaxDepth = 64;           // deeper scenes are not the project's
constexpr std::size_t kMaxName = 1024;  // DEF names longer than this are taken as corruption

class SceneDecoder {
 public:
  SceneDecoder(const Bytes& bytes, const BifsConfig& config, std::uint64_t base, const std::string& file)
      : in_(bytes.data(), bytes.size()), config_(config), base_(base), file_(file) {}

  BitReader& bits() { return in_; }
  void use_names(bool on) { use_names_ = on; }

  Result<SceneNode> node(Ndt ndt, int depth) {
    if (depth > kMaxDepth) {
      return fail(codes::limit::nesting_depth,
                  "scene nested deeper than " + std::to_string(kMaxDepth) + " levels (the depth limit)");
    }
    const bifs::NdtSpec& table = bifs::ndt_spec(ndt);
    if (in_.get_bit()) return fail(codes::bifs::not_decoded, "USE of a node: fapc decodes only scenes without USE");
    const std::uint32_t code = in_.get(table.bits);
    if (in_.failed()) return cut_short();
    if (code == 0)
      return fail(codes::bifs::not_decoded,
                  std::string(table.name) + " node from a later BIFS version: fapc decodes " + "version 1 nodes only");
    const NodeSpec* spec = bifs::node_for_code(ndt, code);
    if (!spec)
      return fail(codes::bifs::bad_node, std::string(table.name) + " node type " + std::to_string(code) +
                                             " is outside the node subset fapc decodes");
    SceneNode n{std::string(spec->name), {}, {}};
    if (in_.get_bit()) {
      const std::uint32_t id = in_.get(config_.node_id_bits) + 1;
      n.def_name = "N" + std::to_string(id);
      if (use_names_) {
        n.def_name.clear();
        for (std::uint32_t c = in_.get(8); c != 0 && !in_.failed(); c = in_.get(8)) {
          if (n.def_name.size() == kMaxName) return fail(codes::bifs::bad_node, "DEF name longer than 1024 bytes");
          n.def_name += static_cast<char>(c);
        }
      }
    }
    if (in_.failed()) return cut_short();
    if (Status s = fields(n, *spec, depth); !s) return s.error();
    return n;
  }

  Diagnostic fail(ErrorCode code, const std::string& message) const {
    return make_error(code, Location::binary(file_, static_cast<std::int64_t>(base_ + in_.bit_position() / 8)),
                      "BIFS: " + message);
  }
  Diagnostic cut_short() const { return fail(codes::bifs::truncated, "scene access unit ends inside a node"); }

 private:
  Status fields(SceneNode& n, const NodeSpec& spec, int depth) {
    const auto count = static_cast<std::uint32_t>(spec.fields.size());
    std::vector<std::pair<std::uint32_t, SceneField>> found;
    auto read_one = [&](std::uint32_t index) -> Status {
      for (const auto& [i, f] : found)
        if (i == index)
          return fail(codes::bifs::bad_node,
                      "field " + std::string(spec.fields[index].name) + " of " + n.type + " coded twice");
      SceneField field{std::string(spec.fields[index].name), 0};
      if (Status s = value(spec.fields[index], depth, field.value); !s) return s;
      found.emplace_back(index, std::move(field));
      return ok_status();
    };
    if (in_.get_bit()) {  // mask
      for (std::uint32_t i = 0; i < count; ++i) {
        if (!in_.get_bit()) continue;
        if (Status s = read_one(i); !s) return s;
      }
    } else {  // list
      const int index_bits = bifs::bit_size(count - 1);
      while (!in_.get_bit()) {
        if (in_.failed()) return cut_short();
        const std::uint32_t i = in_.get(index_bits);
        if (i >= count) return fail(codes::bifs::bad_node, n.type + " has no field number " + std::to_string(i));
        if (Status s = read_one(i); !s) return s;
      }
    }
    if (in_.failed()) return cut_short();
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [i, f] : found) n.fields.push_back(std::move(f));
    return ok_status();
  }

  // Reads one field's value into `out`.
  Status value(const FieldSpec& spec, int depth, FieldValue& out) {
    switch (spec.kind) {
      case FieldKind::sf_int32:
        out = static_cast<std::int32_t>(in_.get(32));
        return ok_status();
      case FieldKind::sf_bool:
        out = in_.get_bit();
        return ok_status();
      case FieldKind::sf_float:
        out = std::bit_cast<float>(in_.get(32));
        return ok_status();
      case FieldKind::mf_url:
        return urls(out);
      case FieldKind::uncoded:
        return fail(codes::bifs::not_decoded, "field " + std::string(spec.name) + " is not decoded by fapc");
      case FieldKind::sf_node:
      case FieldKind::mf_node:
        break;
    }
    std::vector<SceneNode> nodes;
    auto read_child = [&]() -> Status {
      auto child = node(spec.ndt, depth + 1);
      if (!child) return child.error();
      nodes.push_back(std::move(*child));
      return ok_status();
    };
    if (Status s = spec.kind == FieldKind::sf_node ? read_child() : mf_field(read_child); !s) return s;
    if (in_.failed()) return cut_short();
    out = std::move(nodes);
    return ok_status();
  }

  // An MFField's items (14496-11 §8.8.3): a reserved bit, then a list (each item after a 0 bit,
  // a 1 bit at the end) or a vector (5 bits of length width, the length, the items).
  template <class Read>
  Status mf_field(Read&& read_item) {
    if (in_.get_bit(), in_.get_bit()) {  // reserved bit, then list (1) or vector (0)
      while (!in_.get_bit()) {
        if (in_.failed()) return cut_short();
        if (Status s = read_item(); !s) return s;
      }
    } else {
      const int length_bits = static_cast<int>(in_.get(5));
      const std::uint32_t length = in_.get(length_bits);
      for (std::uint32_t i = 0; i < length && !in_.failed(); ++i)
        if (Status s = read_item(); !s) return s;
    }
    return in_.failed() ? Status(cut_short()) : ok_status();
  }

  // An MFURL whose SFURLs name object descriptors; a URL string is named, not decoded.
  Status urls(FieldValue& out) {
    std::vector<ObjectUrl> list;
    auto read_url = [&]() -> Status {
      if (!in_.get_bit()) return fail(codes::bifs::not_decoded, "URL strings in an MFURL are not decoded by fapc");
      list.push_back({static_cast<std::uint16_t>(in_.get(10))});
      return ok_status();
    };
    if (Status s = mf_field(read_url); !s) return s;
    out = std::move(list);
    return ok_status();
  }

  BitReader in_;
  const BifsConfig& config_;
  bool use_names_ = false;
  std::uint64_t base_;
  const std::string& file_;
};

}  // namespace

Result<BifsConfig> decode_bifs_config(const Bytes& bytes, std::uint64_t base, const std::string& file) {
  BitReader in(bytes.data(), bytes.size());
  BifsConfig c;
  c.node_id_bits = static_cast<int>(in.get(5));
  c.route_id_bits = static_cast<int>(in.get(5));
  c.command_stream = in.get_bit();
  c.pixel_metric = false;
  c.has_size = false;
  c.width = c.height = 0;
  if (c.command_stream) {
    c.pixel_metric = in.get_bit();
    c.has_size = in.get_bit();
    if (c.has_size) {
      c.width = static_cast<std::uint16_t>(in.get(16));
      c.height = static_cast<std::uint16_t>(in.get(16));
    }
  }
  if (in.failed())
    return make_error(codes::bifs::truncated, Location::binary(file, static_cast<std::int64_t>(base)),
                      "BIFSConfig cut short (" + std::to_string(bytes.size()) + " bytes)");
  if (!c.command_stream)
    return make_error(codes::bifs::not_decoded, Location::binary(file, static_cast<std::int64_t>(base)),
                      "BIFS animation-mask streams (BIFS-Anim) are not decoded by fapc");
  return c;
}

Result<SceneNode> decode_scene_replace(const Bytes& bytes, const BifsConfig& config, std::uint64_t base,
                                       const std::string& file) {
  SceneDecoder decoder(bytes, config, base, file);
  BitReader& in = decoder.bits();
  if (in.get(2) != 3)
    return decoder.fail(codes::bifs::bad_command, "the scene access unit does not start with SceneReplace");
  in.get(6);  // reserved
  decoder.use_names(in.get_bit());
  if (in.get_bit()) return decoder.fail(codes::bifs::not_decoded, "PROTO declarations are not decoded by fapc");
  auto top = decoder.node(Ndt::top, 0);
  if (!top) return top.error();
  if (in.get_bit()) return decoder.fail(codes::bifs::not_decoded, "ROUTEs are not decoded by fapc");
  if (in.get_bit()) return decoder.fail(codes::bifs::bad_command, "more than one command in the scene access unit");
  if (in.failed()) return decoder.cut_short();
  // Zero bytes may follow the command frame (the project's writer adds one, see mp4_writer.cpp).
  while (in.bits_left() > 0)
    if (in.get_bit()) return decoder.fail(codes::bifs::bad_command, "data after the SceneReplace command");
  return std::move(*top);
}

}  // namespace fapc::mpeg4

// BIFS encoding of a SceneReplace command (14496-11 §8.6: BIFSConfig, Command, BIFSScene, SFNode,
// MaskNodeDescription / ListNodeDescription, MFField). Field-by-field choices (mask or list,
// list or vector) follow the cost rule GPAC's encoder uses, so the bits match it.
#include <bit>
#include <cstring>

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

constexpr std::uint32_t kSceneReplaceCommand = 3;  // 2-bit command code

class SceneEncoder {
 public:
  SceneEncoder(const BifsConfig& config, bool use_names) : config_(config), use_names_(use_names) {}

  Status node(const SceneNode& n, Ndt ndt, std::string_view parent) {
    const std::uint32_t code = bifs::node_code(ndt, n.type);
    const NodeSpec* spec = bifs::find_node(n.type);
    if (code == 0 || spec == nullptr)
      return fail("cannot code node " + n.type + " as " + std::string(bifs::ndt_spec(ndt).name) + " (in " +
                  std::string(parent) + "): not in the BIFS subset fapc writes");
    out_.put_bit(false);  // not a USE
    out_.put(code, bifs::ndt_spec(ndt).bits);
    out_.put_bit(!n.def_name.empty());
    if (!n.def_name.empty()) {
      const std::uint32_t id = next_id_++;
      // The all-ones ID is reserved: a USE of it means a NULL node.
      if (id >= (std::uint32_t{1} << config_.node_id_bits))
        return fail("node " + n.def_name + " gets ID " + std::to_string(id) + ", which " +
                    std::to_string(config_.node_id_bits) + "-bit node IDs cannot hold");
      out_.put(id - 1, config_.node_id_bits);
      if (use_names_) {
        if (n.def_name.find('\0') != std::string::npos) return fail("DEF name contains a NUL byte");
        for (const char c : n.def_name) out_.put(static_cast<std::uint8_t>(c), 8);
        out_.put(0, 8);
      }
    }
    return fields(n, *spec);
  }

  Bytes finish() { return out_.finish(); }
  BitWriter& bits() { return out_; }

 private:
  Status fields(const SceneNode& n, const NodeSpec& spec) {
    // Position of each given field in the node's DEF order.
    std::vector<const SceneField*> by_index(spec.fields.size(), nullptr);
    for (const SceneField& f : n.fields) {
      std::size_t i = 0;
      while (i < spec.fields.size() && spec.fields[i].name != f.name) ++i;
      if (i == spec.fields.size()) return fail("node " + n.type + " has no field " + f.name);
      if (by_index[i]) return fail("field " + f.name + " of " + n.type + " given twice");
      by_index[i] = &f;
    }
    const auto count = static_cast<std::uint32_t>(spec.fields.size());
    const int index_bits = bifs::bit_size(count - 1);
    const auto given = static_cast<std::uint32_t>(n.fields.size());
    // A mask costs one bit per field; a list one bit per given field plus its index, and an end.
    const bool use_mask = count < 1 + given * (1 + static_cast<std::uint32_t>(index_bits));
    out_.put_bit(use_mask);
    for (std::uint32_t i = 0; i < count; ++i) {
      if (!by_index[i]) {
        if (use_mask) out_.put_bit(false);
        continue;
      }
      out_.put_bit(use_mask);  // mask: 1 = present; list: 0 = not the end
      if (!use_mask) out_.put(i, index_bits);
      if (Status s = value(*by_index[i], spec.fields[i], n); !s) return s;
    }
    if (!use_mask) out_.put_bit(true);  // end of list
    return ok_status();
  }

  Status value(const SceneField& f, const FieldSpec& spec, const SceneNode& owner) {
    const std::string where = owner.type + "." + f.name;
    switch (spec.kind) {
      case FieldKind::sf_int32:
        if (!std::holds_alternative<std::int32_t>(f.value)) return fail(where + " must be an integer");
        out_.put(static_cast<std::uint32_t>(std::get<std::int32_t>(f.value)), 32);
        return ok_status();
      case FieldKind::sf_bool:
        if (!std::holds_alternative<bool>(f.value)) return fail(where + " must be a boolean");
        out_.put_bit(std::get<bool>(f.value));
        return ok_status();
      case FieldKind::sf_float:
        if (!std::holds_alternative<float>(f.value)) return fail(where + " must be a number");
        out_.put(std::bit_cast<std::uint32_t>(std::get<float>(f.value)), 32);
        return ok_status();
      case FieldKind::mf_url:
        if (!std::holds_alternative<std::vector<ObjectUrl>>(f.value)) return fail(where + " must hold URLs");
        return urls(std::get<std::vector<ObjectUrl>>(f.value), where);
      case FieldKind::uncoded:
        return fail(where + " is not coded by fapc");
      case FieldKind::sf_node:
      case FieldKind::mf_node:
        break;
    }
    if (!std::holds_alternative<std::vector<SceneNode>>(f.value)) return fail(where + " must hold nodes");
    const auto& nodes = std::get<std::vector<SceneNode>>(f.value);
    if (spec.kind == FieldKind::sf_node) {
      if (nodes.size() != 1) return fail(where + " holds exactly one node");
      return node(nodes.front(), spec.ndt, where);
    }
    return mf_field(nodes, [&](const SceneNode& child) { return node(child, spec.ndt, where); });
  }

  // An MFField (14496-11 §8.8.3): a reserved bit, then the items as a list (each after a 0 bit,
  // a 1 bit at the end) or a vector (5 bits of length width, the length, the items).
  template <class Items, class Put>
  Status mf_field(const Items& items, Put&& put) {
    out_.put_bit(false);  // reserved
    const auto n = static_cast<std::uint32_t>(items.size());
    const int length_bits = bifs::bit_size(n);
    // A list costs an end bit per item; a vector 5 bits of width and the length.
    const bool use_list = n == 0 || static_cast<std::uint32_t>(length_bits) + 5 > n + 1;
    out_.put_bit(use_list);
    if (!use_list) {
      out_.put(static_cast<std::uint32_t>(length_bits), 5);
      out_.put(n, length_bits);
    }
    for (const auto& item : items) {
      if (use_list) out_.put_bit(false);
      if (Status s = put(item); !s) return s;
    }
    if (use_list) out_.put_bit(true);
    return ok_status();
  }

  // An MFURL of SFURLs that name object descriptors: isOD 1, then the 10-bit OD ID.
  Status urls(const std::vector<ObjectUrl>& list, const std::string& where) {
    return mf_field(list, [&](const ObjectUrl& u) -> Status {
      if (u.od_id == 0 || u.od_id >= 1024)
        return fail(where + ": OD ID " + std::to_string(u.od_id) + " is not 1..1023");
      out_.put_bit(true);  // isOD
      out_.put(u.od_id, 10);
      return ok_status();
    });
  }

  static Diagnostic fail(const std::string& message) {
    return make_error(codes::bifs::cannot_encode, Location{}, "BIFS encoding: " + message);
  }

  const BifsConfig& config_;
  bool use_names_;
  std::uint32_t next_id_ = 1;
  BitWriter out_;
};

}  // namespace

Bytes encode_bifs_config(const BifsConfig& c) {
  BitWriter w;
  w.put(static_cast<std::uint32_t>(c.node_id_bits), 5);
  w.put(static_cast<std::uint32_t>(c.route_id_bits), 5);
  w.put_bit(c.command_stream);
  if (c.command_stream) {
    w.put_bit(c.pixel_metric);
    w.put_bit(c.has_size);
    if (c.has_size) {
      w.put(c.width, 16);
      w.put(c.height, 16);
    }
  }
  return w.finish();
}

Result<Bytes> encode_scene_replace(const SceneNode& top, const BifsConfig& config, bool use_names) {
  SceneEncoder encoder(config, use_names);
  BitWriter& w = encoder.bits();
  w.put(kSceneReplaceCommand, 2);
  w.put(0, 6);  // reserved
  w.put_bit(use_names);
  w.put_bit(false);  // no PROTO declarations
  if (Status s = encoder.node(top, Ndt::top, "the scene"); !s) return s.error();
  w.put_bit(false);  // no ROUTEs
  w.put_bit(false);  // no further command in this access unit
  return encoder.finish();
}

}  // namespace fapc::mpeg4

// The BIFS version 1 coding tables (ISO/IEC 14496-11 node coding tables) for the nodes the
// project's scenes use: which node data types (NDTs) a node may appear in, with the node's type
// code in each and the NDT's code width, and each node's fields in "DEF" order. Codes and widths
// are the standard's; they were read from GPAC's generated tables (src/bifs/bifs_node_tables.c,
// src/scenegraph/mpeg4_nodes.c) and are checked against GPAC's encoder in tests/xmt.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace fapc::xmt::bifs {

enum class Ndt { top, node3d, fap, viseme, expression, geometry, appearance, fdp, fit, audio };
enum class FieldKind { sf_int32, sf_bool, sf_float, sf_node, mf_node, mf_url, uncoded };

// SFInt32 fields of the FAP node default to "+I", stored as 0x80000000: not initialised.
inline constexpr std::int32_t kUninitialised = INT32_MIN;

struct FieldSpec {
  std::string_view name;
  FieldKind kind;
  Ndt ndt = Ndt::top;  // for node fields: what the child nodes must be
  std::int32_t int_default = 0;
  float float_default = 0.0F;
};

struct NodeSpec {
  std::string_view name;
  std::vector<FieldSpec> fields;  // DEF order: the order of the node's coded fields
};

struct NdtMember {
  std::string_view node;
  std::uint32_t code;  // the node's type code in this NDT (version 1; 0 escapes to version 2)
};

struct NdtSpec {
  Ndt ndt;
  std::string_view name;           // "SF3DNode"
  int bits;                        // width of a type code
  std::vector<NdtMember> members;  // only the subset's nodes
};

const NodeSpec* find_node(std::string_view name);
const NdtSpec& ndt_spec(Ndt ndt);
// The type code of `node` in `ndt`, or 0 when it may not appear there.
std::uint32_t node_code(Ndt ndt, std::string_view node);
// The node with type code `code` in `ndt`, or nullptr when the subset has none.
const NodeSpec* node_for_code(Ndt ndt, std::uint32_t code);

// Bits needed to code values 0..max_value (GPAC's gf_get_bit_size, the standard's "nbBits").
int bit_size(std::uint32_t max_value);

}  // namespace fapc::xmt::bifs

// Realistic generated scripts for the scale benches (issue 19): what batch users write by
// program, made at run time (no stored files), deterministic (the same kind and size always give
// the same text).
//
// Every script is a sequence of "utterance" blocks, each a parallel group of a few elements that
// lasts about 0.1 s per element, so a script of n elements lasts about n / 10 s: 10^6 elements
// fit the default frame limit at 10 fps (10^6 frames) and exceed it at 25 fps.
//
// - mimic: fades, periodic jaw actions, time-value lists, macro uses and nested `{ }` groups,
//   blocks grouped by ten and by a hundred.
// - fml: a story of `seq` actions holding `par` blocks of hdmv, expr, fap, param moves, template
//   uses (behavior) and waits; `normal` now and then.
// - xmto: a body `seq` of `par` blocks holding animate (values/keyTimes, from-to, by, the three
//   calcModes, additive, accumulate with repeatCount, fill freeze) and set (FAPs, visemes,
//   expressions), nested `seq`s.
// - xmto_to: the same with `to`-animations (which start from the underlying value) in every
//   block.
// - bml: BML 1.0 face lexemes, FACS action units and head lexemes placed by sync references; each
//   block's first lexeme starts at the previous block's end, a chain through the document.
//
// "Elements" counts what the front end schedules as leaves before repeats: atomic actions and
// macro uses in Mimic, moves and template uses in FML, animate/set in XMT-Omega, behaviours in BML.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fapc::bench {

enum class ScriptKind { mimic, fml, xmto, xmto_to, bml };

// The kinds in a fixed order, for loops over every front end.
inline constexpr ScriptKind kScriptKinds[] = {ScriptKind::mimic, ScriptKind::fml, ScriptKind::xmto, ScriptKind::xmto_to,
                                              ScriptKind::bml};

const char* name(ScriptKind kind);       // "mimic", "fml", "xmto", "xmto-to", "bml"
const char* extension(ScriptKind kind);  // ".mimic", ".fml", ".xmt", ".xmt", ".bml"
// Parses a name() back; false when unknown.
bool parse_script_kind(std::string_view text, ScriptKind& kind);

// A script of about `elements` elements (at least one block), ready to compile.
std::string generate_script(ScriptKind kind, std::size_t elements);

}  // namespace fapc::bench

// A bml element read inside another language's document: FML-APML (fapc::intent) carries its
// speech and behaviours as a bml part, read and lowered exactly as a BML document's block.
// And a block of a sequence (docs/bml.md, "Several blocks"), placed after the blocks before it.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "bml/sync_solver.hpp"
#include "fapc/bml/bml.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::bml {

// `block` is an element of `doc` named bml (an error at it otherwise). The result's warnings
// leave out the parser's own, which belong to the whole document.
Result<BmlDocument> read_bml_block(const xml::XmlDocument& doc, const xmlNode* block, const BmlOptions& options);

// One behaviour of an earlier block as placed: its points and marks, seconds from the start of
// the sequence. Later blocks may name them (`bml1:nod1:end`).
struct PlacedPoints {
  std::array<double, kStandardPoints> points{};
  std::vector<std::string> mark_ids;
  std::vector<double> marks;
};

// What a block of a sequence needs of the blocks before it.
struct EarlierBlocks {
  double arrival = 0;  // when this block is sent: MERGE and REPLACE start here
  double end = 0;      // when every earlier block has ended: APPEND starts here (or at arrival, if later)
  // block id -> behaviour id -> its points; the block read adds its own.
  std::map<std::string, std::map<std::string, PlacedPoints>> placed;
};

// The document's root block, placed by its composition after `earlier` (its clips, behaviours and
// marks at their times in the sequence), its points added to `earlier.placed`.
Result<BmlDocument> read_sequenced_block(const xml::XmlDocument& doc, const BmlOptions& options,
                                         EarlierBlocks& earlier);

}  // namespace fapc::bml

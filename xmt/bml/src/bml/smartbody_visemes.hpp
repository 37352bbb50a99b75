// SmartBody's viseme names (<lips viseme="BMP">) to MPEG-4 visemes, by fapc's own table
// transcoder/vocabulary/data/smartbody_visemes.tsv (docs/bml.md, "SmartBody").
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapc::bml {

// FAP 1's viseme (0..14) for a SmartBody name, compared ignoring case; nullopt when the table has
// no such name.
std::optional<int> smartbody_viseme(std::string_view name);

// The table's names, in its order (for messages and tests).
std::vector<std::string> smartbody_viseme_names();

}  // namespace fapc::bml

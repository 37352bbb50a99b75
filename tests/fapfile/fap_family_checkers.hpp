// Strict readers of .fap text, one per player family, written from docs/fap-files.md (section 3 for
// each program and section 5 for the safe form), not from fapc's reader: each reads a file the way
// that family's program does and fails, with a reason, on anything that program would misread, and
// on anything outside the exact form fapc promises for that family (docs/fap-files.md, "Flavours").
// They return what the program would see, so a test can compare it with what was written.
#pragma once

#include <bitset>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fapc::test {

struct SeenFrame {
  long long number = 0;           // as written (a row index, or milliseconds for SEMAINE)
  std::bitset<68> mask;           // FAP 1..68
  std::vector<long long> fap1;    // 4 fields, or 1 value
  std::vector<long long> fap2;    // 6 fields, or 1 value
  std::vector<long long> values;  // FAPs 3..68 in the mask, ascending
};

struct Seen {
  std::vector<SeenFrame> frames;
  int fps = 0;        // 0 where the family's reader takes none from the file
  std::string error;  // empty when the file is read as intended
};

enum class Family { safe, xface, greta_cpp, greta_java, vreng, semaine };

Seen read_as(Family family, const std::string& text);

}  // namespace fapc::test

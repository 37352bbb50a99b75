// Which side of the face a FAP moves, read from its standard name: `l`/`lm` in the name is the
// face's left, `r`/`rm` its right (ISO/IEC 14496-2 names both sides of every paired FAP so).
// Readers of one-sided units (BML's "L12", ARKit's ...Left) keep the FAPs of that side.
#pragma once

namespace fapc::vocabulary {

enum class Side { left, right, middle };

Side fap_side(int fap);

// The same FAP on the other side (6 <-> 7, 53 <-> 54); the FAP itself for a middle one.
int mirror_fap(int fap);

}  // namespace fapc::vocabulary

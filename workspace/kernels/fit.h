// FIT: the interpolated grid INTPN from the patch matrices (IGDS manual 3.3 and Appendix III;
// spec docs/kernels.md, "The mathematics").
#pragma once

#include <cstddef>
#include <span>

#include "workspace/kernels/array.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/vec3.h"

namespace igds {

// Rows and columns of INTPN: NOCUR + INTCU(NOCUR-1) by NOSTR + INTST(NOSTR-1).
struct GridShape {
  std::size_t rows = 0, cols = 0;
};
GridShape intpn_shape(int nocur, int nostr, int intcu, int intst);

// INTPN from PATCHES ((NOCUR-1) x (NOSTR-1) x 3 x 4 x 4): output row I lies in patch row
// min(I div (INTCU+1), NOCUR-2) at v = b/(INTCU+1), likewise columns with u; every patch block
// is W M W^T per coordinate, evaluated relative to the centre of the input points' bounding box.
// The NOCUR x NOSTR input `points` are then copied bit-exactly to their places. Written into
// `intpn`, whose memory is reused when it is large enough (Array::reshape_for_output). Returns the
// index of INTPN's first number that is not finite (patches near the largest numbers overflow),
// or its size when every one is: found as the numbers are made, not by reading INTPN again.
std::size_t fit(int nocur, int nostr, int intcu, int intst, const Array& patches, Vec3View points,
                Array& intpn);

// The same without PATCHES: each row of patch matrices is made from `source` (coons.h) when FIT
// comes to it, on the thread that evaluates it, and not kept; the grid is the same bit for bit.
// Returned: the index PATCHES' first number that is not finite would have ((NOCUR-1)(NOSTR-1)48
// when every one is) and that of INTPN's, as fit returns it.
struct FitResult {
  std::size_t patch_not_finite = 0, intpn_not_finite = 0;
};
FitResult fit(int intcu, int intst, const PatchSource& source, Array& intpn);

}  // namespace igds

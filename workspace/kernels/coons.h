// COONS: the tangents at every grid point and the patch matrices PATCHES (IGDS manual 3.2 and
// Appendix III; spec docs/kernels.md, "The mathematics").
#pragma once

#include <span>
#include <vector>

#include "workspace/kernels/array.h"
#include "workspace/kernels/vec3.h"

namespace igds {

// What a tangent is measured against: IGDS's splines give tangents per unit of chord length, which
// PATCHES scales by the chord of each arc (docs/kernels.md); Marks's tangents (marks.h) are already
// per unit of the patch parameter and go into PATCHES as they are.
enum class TangentUnits { per_chord, per_parameter };

// Tangents at every input point, NOCUR x NOSTR in point-number order: along the curves (the rows)
// and along the stringers (the columns).
struct GridTangents {
  std::vector<Vec3> along_curves;
  std::vector<Vec3> along_stringers;
  TangentUnits units = TangentUnits::per_chord;
};

// The border tangent of INPTG row `row` (x y z; column 4, the point number, is not used: the
// row's place in the order of workspace/state.h says which point it belongs to).
Vec3 border_tangent(const Array& inptg, std::size_t row);

// Splines (CURVILINEO) along every curve and every stringer of the NOCUR x NOSTR points, clamped
// by the border tangents of INPTG (2(NOCUR+NOSTR) x 4, row order as in workspace/state.h).
GridTangents grid_tangents(int nocur, int nostr, Vec3View points, const Array& inptg);

// PATCHES, (NOCUR-1) x (NOSTR-1) x 3 x 4 x 4: per patch and coordinate the matrix M of
// docs/kernels.md, corners, then the tangents (per_chord: scaled by the chord length of their arc;
// per_parameter: as they are, but zero along a zero-length arc, which is its point), then the
// twists: `twists` holds one per input point (per unit of both patch parameters, docs/marks.md), or
// is empty for the zero twists of the manual. Written into `patches`, whose memory is reused when
// it is large enough (Array::reshape_for_output). Returns the index of PATCHES' first number that
// is not finite (tangents near the largest numbers overflow), or its size when every one is.
std::size_t coons_patches(int nocur, int nostr, Vec3View points, const GridTangents& tangents,
                          Array& patches, Vec3View twists = {});

}  // namespace igds

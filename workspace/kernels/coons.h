// COONS: the tangents at every grid point and the patch matrices PATCHES (IGDS manual 3.2 and
// Appendix III; spec docs/kernels.md, "The mathematics").
#pragma once

#include <algorithm>
#include <cstddef>
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

// The tangents along the stringers of the NOCUR x NOSTR `points` into `along` (sized here, on the
// calling thread, which writes it first). A stringer's points lie a row's length apart, so
// neighbouring stringers are copied side by side, a row of them at once, and their tangents copied
// back the same way: `solve(j0, width, columns, out)` makes those of stringers j0 .. j0 + width -
// 1, stringer j0 + c's points at columns + 3 c NOCUR, its tangents into out + c NOCUR.
template <class Solve>
void stringer_tangents(std::size_t nc, std::size_t ns, Vec3View points, std::vector<Vec3>& along,
                       const Solve& solve) {
  reserve_large(along, nc * ns);
  along.resize(nc * ns);
  const std::size_t block = std::clamp<std::size_t>(65536 / std::max<std::size_t>(nc, 1), 1, 16);
  std::vector<double> columns(3 * block * nc);
  std::vector<Vec3> out(block * nc);
  for (std::size_t j0 = 0; j0 < ns; j0 += block) {
    const std::size_t width = std::min(block, ns - j0);
    for (std::size_t i = 0; i < nc; ++i)
      for (std::size_t c = 0; c < width; ++c)
        Vec3(points[i * ns + j0 + c]).store(&columns[3 * (c * nc + i)]);
    solve(j0, width, columns.data(), out.data());
    for (std::size_t i = 0; i < nc; ++i)
      for (std::size_t c = 0; c < width; ++c) along[i * ns + j0 + c] = out[c * nc + i];
  }
}

// Splines (CURVILINEO) along every curve and every stringer of the NOCUR x NOSTR points, clamped
// by the border tangents of INPTG (2(NOCUR+NOSTR) x 4, row order as in workspace/state.h).
GridTangents grid_tangents(int nocur, int nostr, Vec3View points, const Array& inptg);

// What a row of patch matrices is made from: the NOCUR x NOSTR input points, their tangents and
// twists (empty: the zero twists of the manual), as coons_patches takes them.
struct PatchSource {
  std::size_t nocur = 0, nostr = 0;
  Vec3View points;
  const GridTangents* tangents = nullptr;
  Vec3View twists;
};

// Patch row `i` of PATCHES (its NOSTR-1 matrices, 48 numbers each, as coons_patches writes them)
// into `out`. Returns the offset in the row of its first number that is not finite, or
// (NOSTR-1) x 48 when every one is.
std::size_t coons_patch_row(const PatchSource& source, std::size_t i, double* out);

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

// The whole interpolation of a surface: COONS (tangents and patch matrices) then FIT (the grid).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "workspace/kernels/array.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/vec3.h"

namespace igds {

struct SurfaceInput {
  int nocur = 0, nostr = 0, intcu = 0, intst = 0;
  const Array* inppn = nullptr;  // (NOCUR*NOSTR) x 3
  const Array* inptg = nullptr;  // 2(NOCUR+NOSTR) x 4, row order as in workspace/state.h
  // CHANGE TWISTS: false for the zero twists of the manual, true for Marks's (marks.h) in the
  // lower right block of every patch matrix.
  bool marks_twists = false;
};

// What the patch matrices of a grid (not a single curve or stringer) are made of besides its
// input points: the tangents of the splines through them, and its twists (empty: the manual's
// zero block). Made once for a surface, and kept with it (workspace/state.h, kept_splines).
struct SplineTangents {
  GridTangents tangents;
  Array twists;
};

struct Surface {
  Array patches;  // PATCHES: (NOCUR-1) x (NOSTR-1) x 3 x 4 x 4
  Array intpn;    // INTPN: (NOCUR+INTCU(NOCUR-1)) x (NOSTR+INTST(NOSTR-1)) x 3
  // A grid's tangents and twists, made on the way (none for a single curve or stringer).
  std::shared_ptr<const SplineTangents> tangents = nullptr;
  // The same surface: the same numbers (the tangents follow from the inputs).
  friend bool operator==(const Surface& a, const Surface& b) {
    return a.patches == b.patches && a.intpn == b.intpn;
  }
};

// A surface of a single curve (NOCUR 1) or stringer (NOSTR 1) as the spline of its points: the
// points, their clamped spline tangents (docs/kernels.md) and the points inserted between two.
// The caller checked the shapes of INPPN and INPTG.
struct LineSpline {
  bool curve = false;  // along the curve (NOCUR 1), else along the stringer
  std::size_t inserted = 0;
  Vec3View points;
  std::vector<Vec3> tangents;
  // The points of the interpolated line.
  std::size_t count() const { return points.size() + inserted * (points.size() - 1); }
};
LineSpline line_spline(const SurfaceInput& in);

// COONS then FIT; for a single curve (NOCUR 1) or stringer (NOSTR 1) the spline of its points,
// and PATCHES empty ((NOCUR-1) x (NOSTR-1) x 3 x 4 x 4 with a 0). Throws DataError
// (workspace/kernels/data_error.h) for data that cannot be interpolated: a non-finite coordinate or
// tangent (naming the point), shapes that do not match. A result that overflowed is returned as
// it is (interpolate_into says so).
Surface interpolate(const SurfaceInput& input);

// What makes the patch matrices of a grid (not a single curve or stringer) a row at a time
// (coons.h, PatchSource): its input points with their tangents and twists, made here unless
// `made` holds those of the same inputs. Throws DataError as interpolate does (the inputs are
// checked either way).
class PatchMaker {
 public:
  explicit PatchMaker(const SurfaceInput& input,
                      std::shared_ptr<const SplineTangents> made = nullptr);
  PatchMaker(const PatchMaker&) = delete;  // the source points into the tangents
  PatchMaker& operator=(const PatchMaker&) = delete;
  const PatchSource& source() const { return source_; }
  const std::shared_ptr<const SplineTangents>& tangents() const { return made_; }

 private:
  std::shared_ptr<const SplineTangents> made_;
  PatchSource source_;
};

// COONS alone: the PATCHES interpolate keeps, for a surface made with PatchesOut::dropped whose
// patches are asked for later (from the tangents it made, when `made` holds them). Throws
// DataError as interpolate does.
Array surface_patches(const SurfaceInput& input,
                      std::shared_ptr<const SplineTangents> made = nullptr);

// FIT alone, for CHANGE GRID: INTPN for new INTCU/INTST from PATCHES already computed. The input
// points are copied bit-exactly to their places in the grid. A single curve or stringer has no
// patches: its grid is made from INPPN and INPTG again.
Array refit(const SurfaceInput& input, const Array& patches);

// The same, written into arrays the caller already holds: their memory is reused when it is large
// enough (a recompute of a surface of the same size then writes no fresh pages, which on a large
// grid costs more than the interpolation itself). All checks of the inputs come first: on
// DataError thrown the output is unchanged. A surface computed from finite inputs can still
// overflow when they are near the largest numbers (a tangent of 1E308): returned is the DataError
// for its first number that is not finite, patch_not_finite naming the patch (row by row from 1),
// or grid_point_not_finite naming INTPN's row and column, found by the kernels as they make the
// numbers (nullopt: every one is finite). The output is overwritten then: a surface that overflowed
// is never kept.
// With PatchesOut::dropped the patch matrices are made a row at a time as FIT evaluates them and
// not kept: `out.patches` is left without a shape (a single curve or stringer's empty PATCHES
// excepted), INTPN is the same bit for bit, and a patch that is not finite is still reported.
enum class PatchesOut { kept, dropped };
[[nodiscard]] std::optional<DataError> interpolate_into(const SurfaceInput& input, Surface& out,
                                                        PatchesOut patches = PatchesOut::kept);
[[nodiscard]] std::optional<DataError> refit_into(const SurfaceInput& input, const Array& patches,
                                                  Array& intpn);

}  // namespace igds

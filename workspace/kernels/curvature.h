// The curvature of the interpolated curves and stringers, for DISPLAY COMBS (docs/kernels.md,
// "Curvature"): from the exact derivatives of the bicubic patches, not from differences of INTPN.
#pragma once

#include <cstddef>
#include <vector>

#include "workspace/kernels/array.h"
#include "workspace/kernels/conic_lanes.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/project.h"
#include "workspace/kernels/surface.h"
#include "workspace/kernels/vec3.h"

namespace igds {

// The curvature vector of a curve with first and second derivatives d1, d2 at a point: the
// curvature times the unit normal towards the centre of curvature, (d2 - (d2.T)T) / |d1|^2 with
// T = d1/|d1|; zero where the curve has no direction (d1 = 0), not finite where d1 or d2 is not.
Vec3 curvature_vector(Vec3 d1, Vec3 d2);

// At every point of INTPN (rows x cols of intpn_shape), the curvature vector of the curve through
// it, then of the stringer through it: rows x cols x 6. Each point is evaluated in the patch FIT
// takes it from (a point on a patch border: the patch after it, the last patch for the last
// line). A single curve or stringer (no patches) is the spline of its points, and the other
// direction has no curvature. `patches` is PATCHES of `input` (not read for a single line). Throws
// DataError for arrays of another shape.
Array grid_curvature(const SurfaceInput& input, const Array& patches);

// The largest length of some curvature vectors (the scale of their combs): the largest square that
// is finite, and the largest length among the vectors whose square is not (zero for none); a
// vector that is not finite has none.
struct LargestCurvature {
  double squared = 0, overflowing = 0;
  void add(Vec3 k);
  void add(const LargestCurvature& other);
  double length() const;
};

// A point's two curvature vectors (the curve's, then the stringer's) measured into `largest`, and
// with `map` (a parallel projection: linear, kernels/project.h) their images by its linear part
// written to images[0..4): the curve's x y, then the stringer's.
void comb_vectors(Vec3 along, Vec3 across, const ProjectiveMap* map, double* images,
                  LargestCurvature& largest);

// The combs' images of n points from the images of their curvature vectors (combs[4k..4k+4), as
// comb_vectors writes them) and the points' images (points[2k..2k+2)): each end is its point's
// image less `scale` times its vector's, written over it. Returns the first comb (two a point)
// whose end is not finite, or 2 n.
std::size_t comb_images(const double* points, double* combs, std::size_t n, double scale);

// A point's two comb ends in space, p - scale k (the curve's, then the stringer's), into
// out[0..6).
void comb_ends(Vec3 p, Vec3 along, Vec3 across, double scale, double* out);

// grid_curvature for rows of INTPN, a few at a time, on the calling thread: for work on a large
// grid (not for a single line). With `source`, each row of patch matrices is made from it as it is
// needed and `patches` is not read. One per thread: it keeps its buffers, and the row of patch
// matrices it made last, from one call to the next. Throws DataError for arrays of another shape.
class CurvatureRows {
 public:
  CurvatureRows(const SurfaceInput& input, const Array& patches,
                const PatchSource* source = nullptr);
  // Rows [first, last) into `out` (6 (last - first) cols numbers).
  void operator()(std::size_t first, std::size_t last, double* out);
  // Rows [first, last): the CONIC images seen from `eye` (`frame`: kernels/conic_lanes.h) of
  // their combs' ends (comb_ends of their points, `points`: 3 (last - first) cols numbers, INTPN's)
  // into `images` (4 (last - first) cols numbers: the curve's comb's x y, then the stringer's),
  // with what project_part finds of them (not_finite counts the combs, two a point); their
  // curvature vectors measured into `largest`.
  ProjectedPart conic_combs(std::size_t first, std::size_t last, const double* points, double scale,
                            const ConicFrame& frame, Vec3 eye, double* images,
                            LargestCurvature& largest);
  // Rows [first, last) not kept: comb_vectors of each point, the images to `images` (4 (last -
  // first) cols numbers) with `map`.
  void combs(std::size_t first, std::size_t last, LargestCurvature& largest,
             const ProjectiveMap* map = nullptr, double* images = nullptr);

 private:
  template <class Sink>
  void each_row(std::size_t first, std::size_t last, Sink& sink);

  SurfaceInput in_;
  const Array& patches_;
  const PatchSource* source_;
  std::size_t cols_, patches_in_row_, step_;
  std::vector<double> column_u_;  // u of a patch's columns, the last patch's last at u = 1
  std::vector<double> made_;      // the row of patch matrices made last from `source`
  std::size_t made_row_ = std::size_t(-1);
};

}  // namespace igds

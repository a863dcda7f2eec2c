// The projections of DISPLAY (manual section 4.4 and 7: ORTHOG, ISOM, CONIC, ASSON), behind one
// entry point: a View (DESIM[2] and its parameters) applied to points, or as a projective map for
// the curves of a drawing (workspace/drawing/project.h).
#pragma once

#include <array>
#include <cstddef>

#include "workspace/kernels/vec3.h"

namespace igds {

// DESIM[2]: the projection codes of the manual.
enum class Projection : int { conic = 1, assonometric = 2, isometric = 3, orthogonal = 4 };

// DESIM[3] for ORTHOGONAL: the plane of projection, as the manual numbers them.
enum class Plane : int { xy = 1, xz = 2, yz = 3 };

// A projection and its parameters as DESIM[3 4 5] holds them: CONIC the view point x y z;
// ASSONOMETRIC the three angles; ISOMETRIC the axis (1 2 3) and the angle; ORTHOGONAL the plane
// code.
struct View {
  Projection projection = Projection::orthogonal;
  std::array<double, 3> parameters{1, 0, 0};
  friend bool operator==(const View&, const View&) = default;
};

// True when the parameters are in range for the projection (CONIC: finite numbers; the eye's
// place against the points is checked when projecting).
bool view_parameters_valid(const View& view);

// The entry point: `in` projected as `view` says into `out` (as long as `in`). CONIC looks from
// the view point at `centre`, the centre of the input points' bounding box; the other projections
// ignore it. Throws DataError (projection_parameters, behind_eye, view_at_centre) before writing
// anything. A large `in` is projected on the machine's cores.
void project(const View& view, Vec3 centre, Vec3View in, MutablePoint2View out);

// The same for the points of an image (DISPLAY INPUT, DISPLAY SURFACE), in one pass over them:
// CONIC also refuses a view point inside the points' bounding box (view_inside_box, before any
// other report but projection_parameters). Finds the index of the first point whose image is
// not finite (finite points near the largest numbers overflow), in.size() when every one is, and
// the box of the images, x0 y0 x1 y1 (of use when every one is finite); with `box_of_points`, the
// points' bounding box too (bounding_box's, found in the same pass). Throws the DataErrors of
// project(), after writing: `out` holds nothing to use then.
struct ProjectedImage {
  std::size_t not_finite = 0;
  std::array<double, 4> extent{};
  Box3 points;
};
ProjectedImage project_image(const View& view, Vec3 centre, Vec3View in, MutablePoint2View out,
                             bool box_of_points = false);

// project_image's one pass without its refusals, for an image projected a part at a time (DISPLAY
// COMBS's ends): every image is written, and the part says what the whole image's checks need,
// the first point whose image is not finite (in.size() for none) and, for CONIC, whether a point
// is not in front of the eye and the box of the points about the eye (p - eye: it holds 0 when the
// eye is in the points' box). Throws DataError (projection_parameters, view_at_centre) before
// writing anything.
struct ProjectedPart {
  std::size_t not_finite = 0;
  bool behind = false;
  Box3 about_eye;
};
ProjectedPart project_part(const View& view, Vec3 centre, Vec3View in, MutablePoint2View out);

// The same projection as a map of homogeneous coordinates: (X h, Y h, h) = M (x, y, z, 1). The
// parallel projections are linear maps (M's last column is 0 0 1) with h = 1; CONIC has h the depth
// along the line of sight divided by D, positive in front of the eye. A rational curve maps to a
// rational curve of the same degree with its weights multiplied by h (the drawing's projection uses
// this to keep curves exact).
struct ProjectiveMap {
  double m[3][4] = {};
  bool perspective = false;
  // X, Y and h of a point.
  std::array<double, 3> apply(Vec3 p) const;
};
ProjectiveMap projection_map(const View& view, Vec3 centre);

// The manual's four functions, which project() dispatches to.
// ORTHOGONAL plane: 1 XY -> (x, y), 2 XZ -> (x, z), 3 YZ -> (y, z) (DESIM[3] of the manual).
void orthog(Vec3View in, int plane, MutablePoint2View out);
// ISOMETRIC: axis 1, 2, 3 (x, y, z) dropped, angle in degrees, 0..90 (docs/kernels.md).
void isom(Vec3View in, int axis, double angle_degrees, MutablePoint2View out);
// CONIC from view point V towards the centre C of the input's bounding box (docs/kernels.md).
void conic(Vec3View in, Vec3 view, Vec3 centre, MutablePoint2View out);
// ASSONOMETRIC (axonometric) with the angles between the projected x-y, y-z, z-x axes, each
// strictly between 90 and 180 degrees, summing to 360 (docs/kernels.md).
void asson(Vec3View in, std::array<double, 3> angles_degrees, MutablePoint2View out);
// PROSPAR, the parallel projection ASSON makes of its scaled points, with the manual's two
// angles a1 a2 in degrees: X = y cos a2 - x cos a1, Y = z - (x sin a1 + y sin a2).
void prospar(Vec3View in, std::array<double, 2> angles_degrees, MutablePoint2View out);

// Parameter checks, shared by the kernels and by the prompts that ask for them.
bool isom_parameters_valid(double axis, double angle_degrees);
bool asson_parameters_valid(std::array<double, 3> angles_degrees);

// The bounding box of a set of points (empty for none).
Box3 bounding_box(Vec3View points);
// Centre of the bounding box of a set of points (the CONIC centre, the local origin).
Vec3 bounding_box_centre(Vec3View points);
// True when `p` lies inside (or on) the bounding box of `points`.
bool inside_bounding_box(Vec3View points, Vec3 p);

}  // namespace igds

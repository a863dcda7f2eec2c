// The projections of DISPLAY (manual section 4.4 and 7: ORTHOG, ISOM, CONIC, ASSON) and SCALE.
#pragma once

#include <array>
#include <span>

#include "workspace/kernels/vec3.h"

namespace igds {

// ORTHOGONAL plane: 1 XY -> (x, y), 2 XZ -> (x, z), 3 YZ -> (y, z) (DESIM[3] of the manual).
void orthog(std::span<const Vec3> in, int plane, std::span<Point2> out);

// ISOMETRIC: axis 1, 2, 3 (x, y, z) dropped, angle in degrees, 0..90 (math.md).
void isom(std::span<const Vec3> in, int axis, double angle_degrees, std::span<Point2> out);

// CONIC from view point V towards the centre C of the input's bounding box (math.md). Throws
// DataError("INCORRECT PARAMETER") when a point is behind the eye or V equals C.
void conic(std::span<const Vec3> in, Vec3 view, Vec3 centre, std::span<Point2> out);

// ASSONOMETRIC (axonometric) with the angles between the projected x-y, y-z, z-x axes, each
// strictly between 90 and 180 degrees, summing to 360 (math.md). Throws DataError otherwise.
void asson(std::span<const Vec3> in, std::array<double, 3> angles_degrees, std::span<Point2> out);

// Parameter checks, shared by the kernels and by the prompts that ask for them.
bool isom_parameters_valid(double axis, double angle_degrees);
bool asson_parameters_valid(std::array<double, 3> angles_degrees);

// Centre of the bounding box of a set of points (the CONIC centre, the local origin).
Vec3 bounding_box_centre(std::span<const Vec3> points);
// True when `p` lies inside (or on) the bounding box of `points`.
bool inside_bounding_box(std::span<const Vec3> points, Vec3 p);

// SCALE: the uniform scale and offset that fit the points' bounding box into the rectangle
// [x0, x1] x [y0, y1], aspect kept, centred, after removing `margin` (a fraction of the
// rectangle's smaller side) on every side. A single point or a line still maps inside.
struct Scaling {
  double scale = 1, offset_x = 0, offset_y = 0;
  Point2 apply(Point2 p) const { return {offset_x + scale * p.x, offset_y + scale * p.y}; }
};
struct Rect {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};
Scaling scale_into(std::span<const Point2> points, Rect target, double margin);

}  // namespace igds

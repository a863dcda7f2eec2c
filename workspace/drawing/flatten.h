// Curves become polylines only where they are drawn, in device units, to a stated tolerance
// (never a fixed number of pieces).
#pragma once

#include <span>
#include <vector>

#include "workspace/kernels/vec3.h"

namespace igds {

// Appends to `out` the points of a polyline that stays within `tolerance` of the Bézier span of
// `degree` (2 or 3) with `controls` (degree + 1 points) and `weights` (empty: polynomial; else
// positive, one per control point), from its first point to its last. Rational spans are split
// in homogeneous coordinates (de Casteljau), so conic arcs flatten as exactly as cubics. The
// first point is appended only when `out` is empty; the span's last point always ends `out`.
void flatten_span(int degree, std::span<const Point2> controls, std::span<const double> weights,
                  double tolerance, std::vector<Point2>& out);

}  // namespace igds

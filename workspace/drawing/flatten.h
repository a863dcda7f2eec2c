// Curves become polylines only where they are drawn, to a stated tolerance (never a fixed number
// of pieces): in device units on the devices, in a picture's own units in a DUCT file. Their
// exact extent is here too, where a box must hold the curve itself, not its controls.
#pragma once

#include <cstddef>
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
// The same in space.
void flatten_span(int degree, std::span<const Vec3> controls, std::span<const double> weights,
                  double tolerance, std::vector<Vec3>& out);

// The points strictly inside the Bézier span of `degree` with `controls` and `weights` (as
// above, but a cubic must be polynomial) where the derivative of a coordinate vanishes, at
// `out`; returns how many (at most 6). With its two ends they are the extremes of each
// coordinate over the span: its tight box.
std::size_t span_extremes(int degree, std::span<const Vec3> controls,
                          std::span<const double> weights, Vec3 out[6]);

}  // namespace igds

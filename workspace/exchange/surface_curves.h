// An IGDS surface leaves igds exactly (docs/exchange.md, "A surface, exactly"): every curve and
// stringer of INTPN is a chain of cubic arcs, so it is a chain of cubic Bézier spans, and every
// patch is a bicubic Bézier net (edge controls at P ± T/3 after the chord scaling). DUCT
// pictures, IGES and STEP files are written from these.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "workspace/drawing/drawing.h"
#include "workspace/kernels/surface.h"
#include "workspace/kernels/vec3.h"

namespace igds {

// The pen of the input points, their border and their border tangents in a surface's drawing
// (the surface's curves and stringers have pen 1).
inline constexpr int input_pen = 2;
// Half side of an input point's square, in device units (as devices/layout.h draws them).
inline constexpr double input_mark_size = 3;

// The surface as a drawing in space, exactly:
// - curve I (1-based, NOCUR + INTCU(NOCUR-1) of them): the iso-line of INTPN row I, one cubic
//   Bézier span per patch (Role::curve, index I), then stringer J likewise (Role::stringer);
//   span ends are INTPN's points, the inner controls P0 + D0/3 and P1 - D1/3 with D the
//   derivatives of the patch's Hermite form at that row or column (docs/exchange.md);
// - in pen 2: the border of the input grid as one closed polyline (Role::border), every non-zero
//   border tangent as a line from its point (Role::tangent, index the point, detail 1 along the
//   curve, 0 along the stringer), the longest a quarter of the input points' largest extent (as
//   DISPLAY INPUT draws its arrows), and a square at every input point (Role::point, index k).
// Throws DataError (shape) when PATCHES or INTPN do not have the shapes of `input`.
Drawing3 surface_curves(const SurfaceInput& input, const Surface& surface);
// The same from PATCHES and INTPN where they are (the workspace's own, not copied).
Drawing3 surface_curves(const SurfaceInput& input, const Array& patches, const Array& intpn);

// The whole surface as one bicubic Bézier net: (3(NOCUR-1)+1) rows by (3(NOSTR-1)+1) columns of
// x y z, row 3i + b and column 3j + a holding control (a, b) of patch (i, j) (a along the curves,
// u; b along the stringers, v). Neighbouring patches share their border rows and columns, which
// are bit for bit the same from either side; the input points are at rows 3i, columns 3j,
// bit-exactly. Throws DataError (shape) when PATCHES does not have the shape of `input`.
struct BezierNet {
  std::size_t rows = 0, cols = 0;
  std::vector<double> xyz;  // rows x cols x 3
  Vec3 at(std::size_t row, std::size_t col) const {
    return Vec3::load(&xyz[3 * (row * cols + col)]);
  }
};
BezierNet surface_net(const SurfaceInput& input, const Array& patches);

// The Bézier controls of input curve i (0-based), as the net holds them (row 3i), and of input
// stringer j (column 3j).
std::vector<double> input_curve_controls(const BezierNet& net, std::size_t i);
std::vector<double> input_stringer_controls(const BezierNet& net, std::size_t j);

// An input curve or stringer as a cubic B-spline in the spline's own parameter, the running chord
// length (0 at the first point, the sum of the chords |P_k+1 - P_k| at point k+1), in which it
// is C2 (the spline system is the C2 condition with the chords as knot spacings): distinct knots
// t_0 < ... < t_n with multiplicities 4, 1, ..., 1, 4, and n + 3 de Boor points. Span k's inner
// Bézier controls divide the leg d_k+1 d_k+2 in the ratios h_k-1 : h_k : h_k+1 of the spans'
// lengths (blossoming), so d_k+1 = b_3k+1 - (h_k-1/h_k)(b_3k+2 - b_3k+1), d_0 = P_0,
// d_n+1 = b_3n-1, d_n+2 = P_n: the same curve to rounding. Spans of zero length (equal input
// points) are left out, their four controls being one point; nullopt when every span has zero
// length (the curve is a point, a pole).
struct CubicBspline {
  std::vector<Vec3> controls;
  std::vector<double> knots;        // distinct, increasing
  std::vector<int> multiplicities;  // one per knot
};
std::optional<CubicBspline> input_curve_bspline(const BezierNet& net, std::size_t i);
std::optional<CubicBspline> input_stringer_bspline(const BezierNet& net, std::size_t j);

}  // namespace igds

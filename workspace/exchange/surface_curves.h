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
  Ravel xyz;           // rows x cols x 3, each written once (not zeroed first)
  double largest = 0;  // the largest magnitude in xyz; infinite when one is not finite
  Vec3 at(std::size_t row, std::size_t col) const {
    return Vec3::load(&xyz[3 * (row * cols + col)]);
  }
};
BezierNet surface_net(const SurfaceInput& input, const Array& patches);

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
// Those of every input curve, then of every input stringer, made on the cores for a large net.
std::vector<std::optional<CubicBspline>> input_bsplines(const BezierNet& net);

// The patches as faces of one shell (EXPORT's FACES, docs/exchange.md): a vertex at every node of
// the input grid, an edge along every patch border (the border's four controls, a Bézier curve),
// each patch a face bounded by its four edges, neighbours sharing theirs, so that the shell is
// sewn as written. An edge whose four controls are one point (along a pole) is left out of its
// faces' loops, and the nodes it joins are one vertex. Edges are numbered along the curves first
// (curve i, from node j: i * (NOSTR-1) + j), then along the stringers (stringer j from node i:
// NOCUR * (NOSTR-1) + i * NOSTR + j).
class PatchShell {
 public:
  PatchShell(const BezierNet& net, std::size_t nc, std::size_t ns) : net_(net), nc_(nc), ns_(ns) {
    vertex_.resize(nc * ns);
    for (std::size_t i = 0; i < nc; ++i)
      for (std::size_t j = 0; j < ns; ++j) {
        std::size_t v = i * ns + j;
        if (j > 0 && degenerate(true, i, j - 1))
          v = vertex_[i * ns + j - 1];
        else if (i > 0 && degenerate(false, i - 1, j))
          v = vertex_[(i - 1) * ns + j];
        vertex_[i * ns + j] = v;
      }
  }
  std::size_t along_count() const { return nc_ * (ns_ - 1); }   // edges along the curves
  std::size_t across_count() const { return (nc_ - 1) * ns_; }  // edges along the stringers
  // Edge (i, j) along curve i from node j (along), or along stringer j from node i: its controls
  // are all one point.
  bool degenerate(bool along, std::size_t i, std::size_t j) const {
    const double* first = control(along, i, j, 0);
    for (int k = 1; k < 4; ++k) {
      const double* p = control(along, i, j, k);
      if (p[0] != first[0] || p[1] != first[1] || p[2] != first[2]) return false;
    }
    return true;
  }
  // The net index of control k (0..3) of an edge.
  std::size_t control_index(bool along, std::size_t i, std::size_t j, int k) const {
    return along ? 3 * i * net_.cols + 3 * j + std::size_t(k)
                 : (3 * i + std::size_t(k)) * net_.cols + 3 * j;
  }
  std::size_t edge(bool along, std::size_t i, std::size_t j) const {
    return along ? i * (ns_ - 1) + j : along_count() + i * ns_ + j;
  }
  // The vertex (a node number, row by row) that stands for node (i, j).
  std::size_t vertex(std::size_t i, std::size_t j) const { return vertex_[i * ns_ + j]; }

 private:
  const double* control(bool along, std::size_t i, std::size_t j, int k) const {
    return &net_.xyz[3 * control_index(along, i, j, k)];
  }
  const BezierNet& net_;
  std::size_t nc_, ns_;
  std::vector<std::size_t> vertex_;
};

}  // namespace igds

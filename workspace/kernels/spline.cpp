#include "workspace/kernels/spline.h"

#include <algorithm>
#include <cassert>

namespace igds {

namespace {

// The C2 system on distinct points q (m >= 2), tangents into tg; cp is work space of size m.
// Thomas algorithm with the known end tangents as rows 0 and m-1 (cp[0] = 0 moves L_1 TG_0 to the
// right-hand side of row 1); the interior rows are spline_row's (spline.h).
template <class Points>
void solve(const Points& q, Vec3 first, Vec3 last, std::span<Vec3> tg, double* cp) {
  const std::size_t m = q.size();
  cp[0] = 0;
  tg[0] = first;
  Vec3 back = q[1] - q[0];
  double lp = chord_length(q[0], q[1]);
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const Vec3 ahead = q[i + 1] - q[i];
    const double ln = chord_length(q[i], q[i + 1]);
    const SplineRow row = spline_row(back, ahead, lp, ln);
    const double pivot = 1 / (row.diagonal - row.lower * cp[i - 1]);
    cp[i] = row.upper * pivot;
    tg[i] = pivot * (row.known - row.lower * tg[i - 1]);
    back = ahead;
    lp = ln;
  }
  tg[m - 1] = last;
  for (std::size_t i = m - 1; i-- > 1;) tg[i] = tg[i] - cp[i] * tg[i + 1];
}

}  // namespace

void spline_tangents(Vec3View points, Vec3 first, Vec3 last, std::span<Vec3> out,
                     SplineScratch& scratch) {
  assert(out.size() == points.size());
  const std::size_t n = points.size();
  if (n == 0) return;
  bool repeated = false;
  for (std::size_t k = 1; k < n && !repeated; ++k) repeated = Vec3(points[k]) == points[k - 1];
  if (!repeated) {
    if (n == 1) {
      out[0] = Vec3{};  // a single point has no direction
      return;
    }
    scratch.upper.resize(n);
    solve(points, first, last, out, scratch.upper.data());
    return;
  }
  // Merge runs of equal consecutive points, solve on the distinct ones and give every duplicate
  // its merged point's tangent (docs/kernels.md, "Choices").
  auto& q = scratch.distinct;
  auto& to = scratch.merged_to;
  q.clear();
  to.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (q.empty() || !(points[k] == q.back())) q.push_back(points[k]);
    to[k] = q.size() - 1;
  }
  const std::size_t m = q.size();
  if (m == 1) {
    // All points coincide (the pole of a sphere octant): no direction to follow.
    std::fill(out.begin(), out.end(), Vec3{});
    return;
  }
  scratch.upper.resize(m);
  scratch.rhs.resize(m);
  solve(std::span<const Vec3>(q), first, last, scratch.rhs, scratch.upper.data());
  for (std::size_t k = 0; k < n; ++k) out[k] = scratch.rhs[to[k]];
}

void spline_tangents(Vec3View points, Vec3 first, Vec3 last, std::span<Vec3> out) {
  SplineScratch scratch;
  spline_tangents(points, first, last, out, scratch);
}

Vec3 spline_arc_point(Vec3 p0, Vec3 p1, Vec3 t0, Vec3 t1, double s) {
  const double len = chord_length(p0, p1);
  Hermite h = hermite(s);
  return h.f0 * p0 + h.f1 * p1 + (len * h.g0) * t0 + (len * h.g1) * t1;
}

}  // namespace igds

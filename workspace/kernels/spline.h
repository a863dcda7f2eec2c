// CURVILINEO: the clamped chord-length cubic spline through one grid line (IGDS manual 3.1 and
// Appendix III; docs/kernels.md, "The mathematics").
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "workspace/kernels/vec3.h"

namespace igds {

// The cubic Hermite blending functions at s in [0, 1] (docs/kernels.md): the manual's A0, A1, B0,
// B1.
struct Hermite {
  double f0, f1, g0, g1;
};
inline Hermite hermite(double s) {
  double s2 = s * s, s3 = s2 * s;
  return {2 * s3 - 3 * s2 + 1, -2 * s3 + 3 * s2, s3 - 2 * s2 + s, s3 - s2};
}

// The chord |p1 - p0| without overflow or underflow (docs/kernels.md, "Choices"): the plain square
// root while the squares are safely representable, std::hypot beyond.
inline double chord_length(Vec3 p0, Vec3 p1) {
  const Vec3 d = p1 - p0;
  const double s = d.x * d.x + d.y * d.y + d.z * d.z;
  if (s > 0x1p-900 && s < 0x1p900) return std::sqrt(s);
  return norm(d);
}

// Row i of the C2 system (docs/kernels.md, coefficients crossed on purpose), for the points before,
// at and after i: lower TG_(i-1) + diagonal TG_i + upper TG_(i+1) = known, with L_(i-1) = |back|
// and L_i = |ahead| the chords. The manual's COEFFICIENTI and NOTO.
struct SplineRow {
  double lower, diagonal, upper;
  Vec3 known;
};
inline SplineRow spline_row(Vec3 back, Vec3 ahead, double lp, double ln) {
  // One division for both ratios: L_(i-1)/L_i = L_(i-1)^2 / (L_i L_(i-1)), and likewise.
  // (Two divisions where the product could leave the normal range.)
  const double product = ln * lp;
  const bool normal = product > 0x1p-960 && product < 0x1p960;
  const double inv = 1 / product;
  const double ratio = normal ? lp * lp * inv : lp / ln;
  const double inverse_ratio = normal ? ln * ln * inv : ln / lp;
  return {ln, 2 * (ln + lp), lp, 3 * (ratio * ahead + inverse_ratio * back)};
}

// Reusable work space of spline_tangents, so that a loop over many grid lines allocates nothing.
struct SplineScratch {
  std::vector<Vec3> distinct;          // the line's points with runs of equal points merged
  std::vector<std::size_t> merged_to;  // for each point, the index of its merged point
  std::vector<double> upper;           // Thomas algorithm: the modified upper diagonal
  std::vector<Vec3> rhs;               // Thomas algorithm: the modified right-hand side
};

// Tangents (per unit of chord length) at every point of one grid line, given the end tangents
// `first` and `last`: the C2 system of docs/kernels.md with the crossed coefficients, solved by the
// Thomas algorithm in O(n). Runs of equal consecutive points are merged, the spline is solved on
// the distinct points and every duplicate gets its merged point's tangent; a line whose points all
// coincide gets zero tangents. `out` has the size of `points`.
void spline_tangents(Vec3View points, Vec3 first, Vec3 last, std::span<Vec3> out,
                     SplineScratch& scratch);
void spline_tangents(Vec3View points, Vec3 first, Vec3 last, std::span<Vec3> out);

// One grid line of many given to spline_tangents at once.
struct SplineLine {
  Vec3View points;
  Vec3 first, last;
  std::span<Vec3> out;
};
// spline_tangents of each line, bit for bit. Lines of as many points without a repeat are solved
// four at a time, a point of each in turn: a line's solve waits on a division at each point, and
// the other lines' work fills the wait.
void spline_tangents(std::span<const SplineLine> lines, SplineScratch& scratch);

// The point at s in [0, 1] of the arc from p0 to p1 with tangents t0, t1 per unit of length: the
// tangents are scaled by the chord length |p1 - p0| (docs/kernels.md), so a zero-length arc is its
// point.
Vec3 spline_arc_point(Vec3 p0, Vec3 p1, Vec3 t0, Vec3 t1, double s);

}  // namespace igds

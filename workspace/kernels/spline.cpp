#include "workspace/kernels/spline.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <vector>

namespace igds {

namespace {

// The C2 system on the distinct points of L lines of m >= 2 points each (q[l], end tangents
// first[l] and last[l]), tangents into tg[l]; cp is work space of L * m. Thomas algorithm with the
// known end tangents as rows 0 and m-1 (cp[0] = 0 moves L_1 TG_0 to the right-hand side of row 1);
// the interior rows are spline_row's (spline.h). Each row waits on a division of the row before:
// the lines' rows are made in turn, so that one line's division runs while another's waits, and
// each line's numbers are those of its own solve.
template <std::size_t L, class Points>
void solve(const std::array<Points, L>& q, const std::array<Vec3, L>& first,
           const std::array<Vec3, L>& last, const std::array<std::span<Vec3>, L>& tg, double* cp) {
  const std::size_t m = q[0].size();
  Vec3 back[L];
  double lp[L];
  for (std::size_t l = 0; l < L; ++l) {
    cp[l] = 0;
    tg[l][0] = first[l];
    back[l] = q[l][1] - q[l][0];
    lp[l] = chord_length(q[l][0], q[l][1]);
  }
  for (std::size_t i = 1; i + 1 < m; ++i) {
    for (std::size_t l = 0; l < L; ++l) {
      const Vec3 ahead = q[l][i + 1] - q[l][i];
      const double ln = chord_length(q[l][i], q[l][i + 1]);
      const SplineRow row = spline_row(back[l], ahead, lp[l], ln);
      const double pivot = 1 / (row.diagonal - row.lower * cp[(i - 1) * L + l]);
      cp[i * L + l] = row.upper * pivot;
      tg[l][i] = pivot * (row.known - row.lower * tg[l][i - 1]);
      back[l] = ahead;
      lp[l] = ln;
    }
  }
  for (std::size_t l = 0; l < L; ++l) tg[l][m - 1] = last[l];
  for (std::size_t i = m - 1; i-- > 1;)
    for (std::size_t l = 0; l < L; ++l) tg[l][i] = tg[l][i] - cp[i * L + l] * tg[l][i + 1];
}

// Whether two consecutive points of the line are equal.
bool has_repeats(Vec3View points) {
  for (std::size_t k = 1; k < points.size(); ++k)
    if (Vec3(points[k]) == points[k - 1]) return true;
  return false;
}

}  // namespace

void spline_tangents(Vec3View points, Vec3 first, Vec3 last, std::span<Vec3> out,
                     SplineScratch& scratch) {
  assert(out.size() == points.size());
  const std::size_t n = points.size();
  if (n == 0) return;
  if (!has_repeats(points)) {
    if (n == 1) {
      out[0] = Vec3{};  // a single point has no direction
      return;
    }
    scratch.upper.resize(n);
    solve<1>(std::array{points}, {first}, {last}, {out}, scratch.upper.data());
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
  solve<1>(std::array{std::span<const Vec3>(q)}, {first}, {last}, {std::span<Vec3>(scratch.rhs)},
           scratch.upper.data());
  for (std::size_t k = 0; k < n; ++k) out[k] = scratch.rhs[to[k]];
}

void spline_tangents(std::span<const SplineLine> lines, SplineScratch& scratch) {
  constexpr std::size_t group = 4;
  // Lines of two points or more without a repeat can share a solve; each line is read for it once.
  std::vector<char> plain(lines.size());
  for (std::size_t k = 0; k < lines.size(); ++k)
    plain[k] = lines[k].points.size() >= 2 && !has_repeats(lines[k].points);
  std::size_t k = 0;
  while (k < lines.size()) {
    // Four such lines of as many points are solved together, any other line alone.
    const std::size_t n = lines[k].points.size();
    bool together = k + group <= lines.size();
    for (std::size_t l = k; together && l < k + group; ++l)
      together = plain[l] && lines[l].points.size() == n;
    if (!together) {
      spline_tangents(lines[k].points, lines[k].first, lines[k].last, lines[k].out, scratch);
      ++k;
      continue;
    }
    std::array<Vec3View, group> points;
    std::array<Vec3, group> first, last;
    std::array<std::span<Vec3>, group> out;
    for (std::size_t l = 0; l < group; ++l) {
      const SplineLine& line = lines[k + l];
      assert(line.out.size() == n);
      points[l] = line.points, first[l] = line.first, last[l] = line.last, out[l] = line.out;
    }
    scratch.upper.resize(group * n);
    solve<group>(points, first, last, out, scratch.upper.data());
    k += group;
  }
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

// CURVILINEO: the clamped chord-length spline (workspace/kernels/spline.h).
#include "workspace/kernels/spline.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "tests/kernels/helpers.h"

using namespace igds;
using igds::test::distance;
using igds::test::Random;

namespace {

// spline_tangents on points kept as objects (the kernel takes a view of doubles).
void spline_of(const std::vector<Vec3>& points, Vec3 first, Vec3 last, std::vector<Vec3>& out,
               SplineScratch* scratch = nullptr) {
  igds::test::Flat<Vec3> flat(points);
  if (scratch)
    spline_tangents(flat, first, last, out, *scratch);
  else
    spline_tangents(flat, first, last, out);
}

// First and second derivatives with respect to the arc length t = s·L of the Hermite arc, from
// the derivatives of F0 F1 G0 G1 (docs/kernels.md), written out independently of the kernel.
Vec3 first_derivative(Vec3 p0, Vec3 p1, Vec3 t0, Vec3 t1, double s) {
  double l = norm(p1 - p0);
  double f0 = 6 * s * s - 6 * s, f1 = -f0, g0 = 3 * s * s - 4 * s + 1, g1 = 3 * s * s - 2 * s;
  return (1 / l) * (f0 * p0 + f1 * p1) + g0 * t0 + g1 * t1;
}
Vec3 second_derivative(Vec3 p0, Vec3 p1, Vec3 t0, Vec3 t1, double s) {
  double l = norm(p1 - p0);
  double f0 = 12 * s - 6, f1 = -f0, g0 = 6 * s - 4, g1 = 6 * s - 2;
  return (1 / (l * l)) * (f0 * p0 + f1 * p1) + (1 / l) * (g0 * t0 + g1 * t1);
}

// The same C2 system (docs/kernels.md) assembled as a dense n x n matrix, rows 0 and n-1 fixing the
// end tangents, solved by Gaussian elimination with partial pivoting: the reference for Thomas.
std::vector<Vec3> dense_solve(const std::vector<Vec3>& p, Vec3 first, Vec3 last) {
  const std::size_t n = p.size();
  std::vector<std::vector<double>> a(n, std::vector<double>(n + 3, 0.0));
  auto set_rhs = [&](std::size_t r, Vec3 v) {
    a[r][n] = v.x, a[r][n + 1] = v.y, a[r][n + 2] = v.z;
  };
  a[0][0] = 1;
  set_rhs(0, first);
  a[n - 1][n - 1] = 1;
  set_rhs(n - 1, last);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    double l_prev = distance(p[i], p[i - 1]), l_next = distance(p[i + 1], p[i]);
    a[i][i - 1] = l_next;
    a[i][i] = 2 * (l_next + l_prev);
    a[i][i + 1] = l_prev;
    set_rhs(i, 3 * ((l_prev / l_next) * (p[i + 1] - p[i]) + (l_next / l_prev) * (p[i] - p[i - 1])));
  }
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    std::swap(a[col], a[pivot]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == col) continue;
      double f = a[r][col] / a[col][col];
      for (std::size_t c = col; c < n + 3; ++c) a[r][c] -= f * a[col][c];
    }
  }
  std::vector<Vec3> t(n);
  for (std::size_t i = 0; i < n; ++i)
    t[i] = (1 / a[i][i]) * Vec3{a[i][n], a[i][n + 1], a[i][n + 2]};
  return t;
}

std::vector<Vec3> random_line(Random& rnd, std::size_t n) {
  std::vector<Vec3> p(n);
  Vec3 at{};
  for (auto& q : p) q = (at = at + rnd.vec(-1, 1) + Vec3{1.5, 0, 0});
  return p;
}

}  // namespace

TEST_CASE("the spline passes through its points and keeps the given end tangents") {
  Random rnd(1);
  auto p = random_line(rnd, 9);
  Vec3 first = rnd.vec(-2, 2), last = rnd.vec(-2, 2);
  std::vector<Vec3> t(p.size());
  spline_of(p, first, last, t);
  CHECK(t.front() == first);
  CHECK(t.back() == last);
  for (std::size_t k = 0; k + 1 < p.size(); ++k) {
    CHECK(distance(spline_arc_point(p[k], p[k + 1], t[k], t[k + 1], 0), p[k]) < 1e-14);
    CHECK(distance(spline_arc_point(p[k], p[k + 1], t[k], t[k + 1], 1), p[k + 1]) < 1e-14);
    // The arc's own derivative at its ends is the tangent: the chord scaling is right.
    CHECK(distance(first_derivative(p[k], p[k + 1], t[k], t[k + 1], 0), t[k]) < 1e-12);
    CHECK(distance(first_derivative(p[k], p[k + 1], t[k], t[k + 1], 1), t[k + 1]) < 1e-12);
  }
}

TEST_CASE("first and second derivatives are continuous at interior points") {
  Random rnd(2);
  for (int trial = 0; trial < 20; ++trial) {
    auto p = random_line(rnd, 3 + trial);
    std::vector<Vec3> t(p.size());
    spline_of(p, rnd.vec(-2, 2), rnd.vec(-2, 2), t);
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      Vec3 d1_left = first_derivative(p[k - 1], p[k], t[k - 1], t[k], 1);
      Vec3 d1_right = first_derivative(p[k], p[k + 1], t[k], t[k + 1], 0);
      Vec3 d2_left = second_derivative(p[k - 1], p[k], t[k - 1], t[k], 1);
      Vec3 d2_right = second_derivative(p[k], p[k + 1], t[k], t[k + 1], 0);
      CHECK(distance(d1_left, d1_right) < 1e-12);
      CHECK(distance(d2_left, d2_right) < 1e-10 * (1 + norm(d2_left)));
    }
  }
}

TEST_CASE("the Thomas algorithm agrees with a dense solve of the same system") {
  Random rnd(3);
  for (std::size_t n : {2u, 3u, 4u, 7u, 30u}) {
    auto p = random_line(rnd, n);
    Vec3 first = rnd.vec(-2, 2), last = rnd.vec(-2, 2);
    std::vector<Vec3> t(n);
    spline_of(p, first, last, t);
    auto reference = dense_solve(p, first, last);
    for (std::size_t k = 0; k < n; ++k) CHECK(distance(t[k], reference[k]) < 1e-12);
  }
}

TEST_CASE("a straight line with unit end tangents has unit tangents everywhere") {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {3.5, 0, 0}, {7, 0, 0}};
  std::vector<Vec3> t(p.size());
  spline_of(p, {1, 0, 0}, {1, 0, 0}, t);
  for (auto v : t) CHECK(distance(v, {1, 0, 0}) < 1e-14);
  // ... and the arc is then traversed at unit speed: the point at s is at s·L along the line.
  CHECK(distance(spline_arc_point(p[3], p[4], t[3], t[4], 0.25), {3.5 + 0.25 * 3.5, 0, 0}) < 1e-14);
}

TEST_CASE("equal consecutive points are merged and share their merged point's tangent") {
  Random rnd(4);
  auto distinct = random_line(rnd, 5);
  Vec3 first = rnd.vec(-1, 1), last = rnd.vec(-1, 1);
  std::vector<Vec3> expected(5);
  spline_of(distinct, first, last, expected);
  // Points 0 and 2 doubled, point 4 tripled.
  std::vector<Vec3> p = {distinct[0], distinct[0], distinct[1], distinct[2], distinct[2],
                         distinct[3], distinct[4], distinct[4], distinct[4]};
  std::vector<std::size_t> merged = {0, 0, 1, 2, 2, 3, 4, 4, 4};
  std::vector<Vec3> t(p.size());
  spline_of(p, first, last, t);
  for (std::size_t k = 0; k < p.size(); ++k) {
    CAPTURE(k);
    CHECK(t[k] == expected[merged[k]]);
  }
  // A zero-length arc evaluates to its point whatever its tangents.
  CHECK(spline_arc_point(p[3], p[4], {5, 6, 7}, {-8, 9, 1}, 0.4) == p[3]);
}

TEST_CASE("a line whose points all coincide gets zero tangents") {
  std::vector<Vec3> p(4, Vec3{1, 2, 3});
  std::vector<Vec3> t(4, Vec3{9, 9, 9});
  spline_of(p, {1, 0, 0}, {0, 1, 0}, t);
  for (auto v : t) CHECK(v == Vec3{});
  std::vector<Vec3> single = {{4, 5, 6}}, single_t(1);
  spline_of(single, {1, 0, 0}, {0, 1, 0}, single_t);
  CHECK(single_t[0] == Vec3{});
}

TEST_CASE("two distinct points keep the given tangents") {
  std::vector<Vec3> p = {{0, 0, 0}, {0, 0, 0}, {1, 1, 1}};
  std::vector<Vec3> t(3);
  spline_of(p, {1, 2, 3}, {4, 5, 6}, t);
  CHECK(t[0] == Vec3{1, 2, 3});
  CHECK(t[1] == Vec3{1, 2, 3});
  CHECK(t[2] == Vec3{4, 5, 6});
}

TEST_CASE("chord lengths do not overflow: tangents are the same at any scale") {
  Random rnd(5);
  auto p = random_line(rnd, 8);
  Vec3 first = rnd.vec(-1, 1), last = rnd.vec(-1, 1);
  std::vector<Vec3> t(8), huge_t(8), tiny_t(8);
  spline_of(p, first, last, t);
  std::vector<Vec3> huge(p), tiny(p);
  for (auto& q : huge) q = 1e200 * q;
  for (auto& q : tiny) q = 1e-200 * q;
  spline_of(huge, first, last, huge_t);
  spline_of(tiny, first, last, tiny_t);
  for (std::size_t k = 0; k < 8; ++k) {
    CHECK(distance(huge_t[k], t[k]) < 1e-12);
    CHECK(distance(tiny_t[k], t[k]) < 1e-12);
  }
}

TEST_CASE("the scratch space can be reused across lines of different lengths") {
  Random rnd(6);
  SplineScratch scratch;
  for (std::size_t n : {12u, 3u, 7u, 1u, 20u}) {
    auto p = random_line(rnd, n);
    Vec3 first = rnd.vec(-1, 1), last = rnd.vec(-1, 1);
    std::vector<Vec3> with(n), without(n);
    spline_of(p, first, last, with, &scratch);
    spline_of(p, first, last, without);
    CHECK(with == without);
  }
}

TEST_CASE("lines given at once have each line's own tangents, bit for bit") {
  // Runs of four lines of as many points are solved together: lines of 9 points, with a repeat
  // among them, with a length of their own, of one and two points, and a run cut short at the end.
  Random rnd(7);
  std::vector<std::vector<Vec3>> points;
  for (std::size_t n :
       {9u, 9u, 9u, 9u, 9u, 9u, 9u, 9u, 9u, 5u, 9u, 9u, 9u, 9u, 2u, 2u, 2u, 2u, 1u, 9u, 9u, 9u})
    points.push_back(random_line(rnd, n));
  points[6][4] = points[6][3];  // the second run of four has a repeat in its third line
  std::vector<igds::test::Flat<Vec3>> flat;
  for (const auto& p : points) flat.emplace_back(p);
  std::vector<Vec3> first, last;
  std::vector<std::vector<Vec3>> together, alone;
  std::vector<SplineLine> lines;
  for (std::size_t k = 0; k < points.size(); ++k) {
    first.push_back(rnd.vec(-1, 1)), last.push_back(rnd.vec(-1, 1));
    together.emplace_back(points[k].size()), alone.emplace_back(points[k].size());
  }
  for (std::size_t k = 0; k < points.size(); ++k)
    lines.push_back({flat[k], first[k], last[k], together[k]});
  SplineScratch scratch;
  spline_tangents(lines, scratch);
  for (std::size_t k = 0; k < points.size(); ++k) {
    spline_of(points[k], first[k], last[k], alone[k]);
    CAPTURE(k);
    CHECK(together[k] == alone[k]);
  }
}

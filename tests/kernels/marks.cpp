// Marks's tangents and twists (workspace/kernels/marks.h) and PATCHES built from them (coons.h),
// checked against the formulas of docs/marks.md and against the report's own sphere octant.
#include "workspace/kernels/marks.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include "tests/kernels/helpers.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/surface.h"

using namespace igds;
using igds::test::distance;
using igds::test::eval_patch;
using igds::test::Flat;
using igds::test::Grid;
using igds::test::Random;
using igds::test::wavy_grid;

namespace {

std::vector<Vec3> tangents_of(const std::vector<Vec3>& points) {
  Flat<Vec3> flat(points);
  std::vector<Vec3> out(points.size(), Vec3{99, 99, 99});
  marks_tangents(flat, out);
  return out;
}

bool same_bits(Vec3 a, Vec3 b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

double rel(Vec3 a, Vec3 b) {
  return distance(a, b) / std::max(1.0, norm(b));
}

// Entry (r, c) of coordinate `k` of patch p in PATCHES (docs/kernels.md's M, row by row).
double entry(const Array& patches, std::size_t p, int k, int r, int c) {
  return patches.ravel[48 * p + 16 * k + 4 * r + c];
}
Vec3 entry3(const Array& patches, std::size_t p, int r, int c) {
  return {entry(patches, p, 0, r, c), entry(patches, p, 1, r, c), entry(patches, p, 2, r, c)};
}

Array grid_of(int nocur, int nostr, const auto& f) {
  Array a({std::size_t(nocur) * nostr, 3});
  auto pts = as_vec3(a);
  for (int i = 0; i < nocur; ++i)
    for (int j = 0; j < nostr; ++j) pts[i * nostr + j] = f(i, j);
  return a;
}

}  // namespace

TEST_CASE("a straight line evenly spaced has the spacing as its tangent everywhere") {
  const Vec3 origin{3, -2, 7}, step{0.5, 1.25, -2};
  std::vector<Vec3> line;
  for (int k = 0; k < 9; ++k) line.push_back(origin + double(k) * step);
  for (Vec3 t : tangents_of(line)) CHECK(rel(t, step) < 1e-14);
}

TEST_CASE("an unevenly spaced straight line keeps every tangent along the line") {
  const Vec3 origin{1, 2, 3}, direction{2, -1, 2};
  std::vector<Vec3> line;
  double s = 0;
  Random rnd(5);
  for (int k = 0; k < 12; ++k) line.push_back(origin + (s += rnd.uniform(0.2, 3)) * direction);
  const auto t = tangents_of(line);
  for (std::size_t k = 0; k < t.size(); ++k) {
    CAPTURE(k);
    CHECK(norm(cross(t[k], direction)) < 1e-12 * norm(t[k]) * norm(direction));
  }
  // Interior points: the length of the shorter chord (F-mesh).
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    const double shorter = std::min(distance(line[k - 1], line[k]), distance(line[k], line[k + 1]));
    CHECK(norm(t[k]) == doctest::Approx(shorter).epsilon(1e-14));
  }
}

TEST_CASE("two points: the chord at both; one point: zero") {
  const auto two = tangents_of({{1, 2, 3}, {4, 6, 3}});
  CHECK(two[0] == Vec3{3, 4, 0});
  CHECK(two[1] == Vec3{3, 4, 0});
  CHECK(tangents_of({{1, 2, 3}})[0] == Vec3{});
  std::vector<Vec3> none;
  CHECK(tangents_of(none).empty());
}

TEST_CASE("the formulas of docs/marks.md on three points") {
  const Vec3 p1{0, 0, 0}, p2{3, 4, 0}, p3{4, 4, 1};
  const auto t = tangents_of({p1, p2, p3});
  // Interior: direction P3 - P1, length min(|P2 - P1|, |P3 - P2|) = sqrt(2).
  const Vec3 across = p3 - p1;
  const Vec3 mid = (std::sqrt(2.0) / norm(across)) * across;
  CHECK(rel(t[1], mid) < 1e-15);
  CHECK(rel(t[0], 2 * (p2 - p1) - mid) < 1e-15);
  CHECK(rel(t[2], 2 * (p3 - p2) - mid) < 1e-15);
}

TEST_CASE("a parabola sampled evenly gets exact end tangents where the F-mesh is exact") {
  // P(t) = a t^2 + b t, t = -1, 0, 1, with |a|^2 = 2 a.b: the shorter chord at t = 0 is |P'(0)|,
  // so the middle tangent is exact and the parabolic ends must be P'(-1) = b - 2a, P'(1) = b + 2a.
  const Vec3 a{1, 1, 0}, b{1, 0, 0};
  auto p = [&](double t) { return (t * t) * a + t * b; };
  const auto t = tangents_of({p(-1), p(0), p(1)});
  CHECK(rel(t[1], b) < 1e-15);
  CHECK(rel(t[0], b - 2 * a) < 1e-15);
  CHECK(rel(t[2], b + 2 * a) < 1e-15);
}

TEST_CASE(
    "on any evenly sampled parabola the end arcs are parabolas, interior tangents exact in "
    "direction") {
  const Vec3 a{0.3, -1.2, 0.7}, b{2, 0.5, -1}, c{10, 20, 30};
  auto p = [&](double t) { return (t * t) * a + t * b + c; };
  std::vector<Vec3> line;
  for (int k = 0; k < 7; ++k) line.push_back(p(k));
  const auto t = tangents_of(line);
  for (int k = 1; k < 6; ++k) {
    const Vec3 exact = (2.0 * k) * a + b;
    CHECK(norm(cross(t[k], exact)) < 1e-13 * norm(t[k]) * norm(exact));
    CHECK(dot(t[k], exact) > 0);
  }
  // The Hermite arc P1 P2 with tangents T1 T2 (per unit of parameter) has cubic coefficient
  // 2P1 - 2P2 + T1 + T2: zero is a parabola.
  CHECK(norm(2 * (line[0] - line[1]) + t[0] + t[1]) < 1e-13);
  CHECK(norm(2 * (line[5] - line[6]) + t[5] + t[6]) < 1e-13);
}

TEST_CASE("equal consecutive points are merged and share their merged point's tangent") {
  const Vec3 a{0, 0, 0}, b{1, 2, 0}, c{3, 2, 1}, d{4, 0, 1};
  const auto merged = tangents_of({a, b, c, d});
  const auto t = tangents_of({a, a, b, c, c, c, d, d});
  const int of[] = {0, 0, 1, 2, 2, 2, 3, 3};
  for (int k = 0; k < 8; ++k) {
    CAPTURE(k);
    CHECK(same_bits(t[k], merged[of[k]]));
  }
  // Two distinct points with duplicates: the chord everywhere.
  for (Vec3 v : tangents_of({a, a, b, b, b})) CHECK(v == b - a);
}

TEST_CASE("a line whose points all coincide has zero tangents (the sphere's pole)") {
  const Vec3 pole{0, 0, 100};
  for (Vec3 v : tangents_of({pole, pole, pole, pole})) CHECK(v == Vec3{});
  // A line that turns back onto its previous point has no direction there.
  const auto t = tangents_of({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}});
  CHECK(t[1] == Vec3{});
  CHECK(t[0] == Vec3{2, 0, 0});
  CHECK(t[2] == Vec3{-2, 0, 0});
}

TEST_CASE(
    "the grid's tangents are the lines' tangents, rows along curves, columns along "
    "stringers") {
  Grid g = wavy_grid(6, 9, 3);
  auto pts = as_vec3(std::as_const(g.inppn));
  // A repeated point in one curve and one stringer.
  as_vec3(g.inppn)[2 * 9 + 5] = pts[2 * 9 + 4];
  as_vec3(g.inppn)[4 * 9 + 7] = pts[3 * 9 + 7];
  const GridTangents t = marks_grid_tangents(6, 9, pts);
  CHECK(t.units == TangentUnits::per_parameter);
  for (int i = 0; i < 6; ++i) {
    std::vector<Vec3> row;
    for (int j = 0; j < 9; ++j) row.push_back(pts[i * 9 + j]);
    const auto expected = tangents_of(row);
    for (int j = 0; j < 9; ++j) CHECK(same_bits(t.along_curves[i * 9 + j], expected[j]));
  }
  for (int j = 0; j < 9; ++j) {
    std::vector<Vec3> column;
    for (int i = 0; i < 6; ++i) column.push_back(pts[i * 9 + j]);
    const auto expected = tangents_of(column);
    for (int i = 0; i < 6; ++i) CHECK(same_bits(t.along_stringers[i * 9 + j], expected[i]));
  }
}

TEST_CASE("AUTO: INPTG holds Marks's end tangents per unit of chord, point numbers in column 4") {
  Grid g = wavy_grid(5, 7, 11);
  auto pts = as_vec3(std::as_const(g.inppn));
  // Curve 2 starts with a repeated point; curve 4 is a single point; stringer 3 ends with a
  // repeated point.
  as_vec3(g.inppn)[2 * 7 + 1] = pts[2 * 7];
  for (int j = 0; j < 7; ++j) as_vec3(g.inppn)[4 * 7 + j] = Vec3{5, 5, 5};
  as_vec3(g.inppn)[3 * 7 + 3] = Vec3{5, 5, 5};
  const Array inptg = marks_border_tangents(5, 7, pts);
  REQUIRE(inptg.shape == std::vector<std::size_t>{24, 4});
  const GridTangents t = marks_grid_tangents(5, 7, pts);
  // The same numbers, bit for bit, as the whole grid's tangents scaled at the border.
  CHECK(inptg == border_tangents_of(5, 7, pts, t));
  auto row = [&](int r) { return Vec3::load(inptg.data() + 4 * r); };
  auto number = [&](int r) { return int(inptg.ravel[4 * r + 3]); };
  for (int i = 0; i < 5; ++i) {
    CHECK(number(2 * i) == i * 7 + 1);
    CHECK(number(2 * i + 1) == i * 7 + 7);
  }
  for (int j = 0; j < 7; ++j) {
    CHECK(number(10 + 2 * j) == j + 1);
    CHECK(number(10 + 2 * j + 1) == 4 * 7 + j + 1);
  }
  // Curve 0: P'(1) / |P2 - P1|, the plain case.
  CHECK(rel(row(0), (1 / distance(pts[0], pts[1])) * t.along_curves[0]) < 1e-15);
  // Curve 2 starts with a zero-length arc: the chord of the first arc of non-zero length.
  CHECK(rel(row(4), (1 / distance(pts[14], pts[16])) * t.along_curves[14]) < 1e-15);
  // Curve 4 (all coincident): zero at both ends.
  CHECK(row(8) == Vec3{});
  CHECK(row(9) == Vec3{});
  // Stringer 3's last arc has zero length: the chord from curve 2 to curve 3.
  CHECK(rel(row(17),
            (1 / distance(pts[2 * 7 + 3], pts[3 * 7 + 3])) * t.along_stringers[4 * 7 + 3]) < 1e-15);
  CHECK(norm(row(17)) > 0);
}

TEST_CASE("AUTO puts exactly Marks's vectors into PATCHES at the border") {
  Grid g = wavy_grid(6, 8, 21);
  auto pts = as_vec3(std::as_const(g.inppn));
  as_vec3(g.inppn)[3 * 8 + 7] = pts[3 * 8 + 6];  // curve 3 ends with a zero-length arc
  g.inptg = marks_border_tangents(6, 8, pts);
  const Surface s = interpolate({6, 8, 0, 0, &g.inppn, &g.inptg});
  const GridTangents t = marks_grid_tangents(6, 8, pts);
  const std::size_t pc = 7;
  for (std::size_t i = 0; i < 6; ++i) {
    CAPTURE(i);
    // Pu at the first point of curve i: patch (i, 0), corner a = 0, b = 0 or 1 (rows 2, cols 0/1).
    const std::size_t first_patch = (i < 5 ? i : 4) * pc, b = i < 5 ? 0 : 1;
    CHECK(rel(entry3(s.patches, first_patch, 2, int(b)), t.along_curves[i * 8]) < 1e-15);
    // Pu at the end of curve i: the last patch whose arc has non-zero length.
    const std::size_t last_arc = i == 3 ? 5 : 6;
    const std::size_t last_patch = (i < 5 ? i : 4) * pc + last_arc;
    CHECK(rel(entry3(s.patches, last_patch, 3, int(b)), t.along_curves[i * 8 + 7]) < 1e-15);
  }
  for (std::size_t j = 0; j < 8; ++j) {
    CAPTURE(j);
    // Pv at the ends of stringer j: rows 0/1 (a), columns 2 (b = 0) and 3 (b = 1).
    const std::size_t col = j < 7 ? j : 6, a = j < 7 ? 0 : 1;
    CHECK(rel(entry3(s.patches, col, int(a), 2), t.along_stringers[j]) < 1e-15);
    CHECK(rel(entry3(s.patches, 4 * pc + col, int(a), 3), t.along_stringers[5 * 8 + j]) < 1e-15);
  }
}

TEST_CASE("PATCHES from tangents per unit of parameter takes them as they are, twists unscaled") {
  Grid g = wavy_grid(4, 5, 8);
  auto pts = as_vec3(std::as_const(g.inppn));
  as_vec3(g.inppn)[1 * 5 + 2] = pts[1 * 5 + 1];  // a zero-length arc along curve 1
  const GridTangents t = marks_grid_tangents(4, 5, pts);
  const Array twists = marks_twists(4, 5, pts);
  Array patches;
  coons_patches(4, 5, pts, t, patches, as_vec3(twists));
  REQUIRE(patches.shape == std::vector<std::size_t>{3, 4, 3, 4, 4});
  auto tw = as_vec3(twists);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 4; ++j) {
      const std::size_t p = i * 4 + j;
      for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) {
          const std::size_t k = (i + b) * 5 + j + a;
          INFO("p=", p, " ", "a=", a, " ", "b=", b);
          CHECK(entry3(patches, p, a, b) == Vec3(pts[k]));
          const bool zero_u = Vec3(pts[(i + b) * 5 + j]) == pts[(i + b) * 5 + j + 1];
          CHECK(entry3(patches, p, 2 + a, b) == (zero_u ? Vec3{} : t.along_curves[k]));
          CHECK(entry3(patches, p, a, 2 + b) == t.along_stringers[k]);
          CHECK(entry3(patches, p, 2 + a, 2 + b) == Vec3(tw[k]));
        }
      }
    }
  }
  // The zero-length arc of patch (1, 1) along its first curve is its point.
  for (double u : {0.25, 0.5, 0.75})
    CHECK(distance(eval_patch(patches.data() + 48 * 5, u, 0), pts[6]) < 1e-13);
}

TEST_CASE(
    "explicit zero twists give the bits of no twists; the twists are the patch's cross "
    "derivative") {
  Grid g = wavy_grid(5, 6, 12);
  auto pts = as_vec3(std::as_const(g.inppn));
  const GridTangents t = grid_tangents(5, 6, pts, g.inptg);
  const Array zero_twists({30, 3});
  Array none, zeros, given;
  coons_patches(5, 6, pts, t, none);
  coons_patches(5, 6, pts, t, zeros, as_vec3(zero_twists));
  REQUIRE(none.shape == zeros.shape);
  CHECK(std::memcmp(none.data(), zeros.data(), none.size() * sizeof(double)) == 0);
  // With twists, d2P/dudv at each corner of each patch is the twist (second differences).
  Array twists({30, 3});
  Random rnd(4);
  for (double& v : twists.ravel) v = rnd.uniform(-2, 2);
  coons_patches(5, 6, pts, t, given, as_vec3(std::as_const(twists)));
  const double h = 1e-4;
  for (std::size_t p : {0u, 7u, 19u}) {
    const double* m = given.data() + 48 * p;
    for (int a = 0; a < 2; ++a) {
      for (int b = 0; b < 2; ++b) {
        const double u = a, v = b, su = a ? -h : h, sv = b ? -h : h;
        const Vec3 mixed =
            (1 / (su * sv)) * (eval_patch(m, u + su, v + sv) - eval_patch(m, u + su, v) -
                               eval_patch(m, u, v + sv) + eval_patch(m, u, v));
        const std::size_t k = (p / 5 + b) * 6 + p % 5 + a;
        INFO("p=", p, " ", "a=", a, " ", "b=", b);
        CHECK(distance(mixed, as_vec3(std::as_const(twists))[k]) < 1e-2);
      }
    }
  }
}

TEST_CASE("a bilinear surface gets its exact constant twist inside, zero at the border") {
  const Vec3 A{1, 2, 3}, B{4, 0, 1}, C{0, 3, -1}, D{0.5, -0.25, 2};
  const Array pts = grid_of(
      5, 7, [&](int i, int j) { return A + double(i) * B + double(j) * C + double(i * j) * D; });
  const Array twists = marks_twists(5, 7, as_vec3(pts));
  REQUIRE(twists.shape == std::vector<std::size_t>{35, 3});
  auto tw = as_vec3(twists);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 7; ++j) {
      INFO("i=", i, " ", "j=", j);
      const bool border = i == 0 || j == 0 || i == 4 || j == 6;
      CHECK(tw[i * 7 + j] == (border ? Vec3{} : D));
    }
  }
}

TEST_CASE("a translational surface has zero twists") {
  const Array pts = grid_of(8, 6, [](int i, int j) {
    return Vec3{std::sin(0.3 * i), 2.0 * i, std::cos(0.2 * i)} +
           Vec3{1.5 * j, std::exp(0.1 * j), 0.3 * j * j};
  });
  const Array twists = marks_twists(8, 6, as_vec3(pts));
  for (Vec3 v : as_vec3(twists)) CHECK(norm(v) < 1e-14);
  // Far from the origin too: differences of neighbours are taken first.
  const Array far = grid_of(4, 4, [](int i, int j) {
    return Vec3{1e12 + i, 1e12 + j, 1e12 + 0.5 * i * i + 0.25 * j};
  });
  const Array far_twists = marks_twists(4, 4, as_vec3(far));
  for (Vec3 v : as_vec3(far_twists)) CHECK(v == Vec3{});
}

// The report's check (docs/marks.md "The paper's check"): an octant of a sphere of radius 100
// divided 20 x 20 in latitude and longitude, with one more row and column of sphere points on every
// side, its corner tangents x 20 and twists x 400 against Coons's quasi-sphere (a = 4(sqrt 2 - 1)).
TEST_CASE("the sphere octant of the report agrees with Coons's quasi-sphere") {
  const double R = 100, step = std::numbers::pi / 40;  // 4.5 degrees
  const int n = 23;                                    // 21 + one more on each side
  // Row i (a curve): colatitude (i - 1) step; column j (a stringer): longitude (j - 1) step.
  // The pole is row 1, the first column runs down to (0, R, 0), the last to (R, 0, 0).
  const Array pts = grid_of(n, n, [&](int i, int j) {
    const double t = (i - 1) * step, f = (j - 1) * step;
    return Vec3{R * std::sin(t) * std::sin(f), R * std::sin(t) * std::cos(f), R * std::cos(t)};
  });
  auto p = as_vec3(pts);
  const GridTangents t = marks_grid_tangents(n, n, p);
  const Array twists = marks_twists(n, n, p);
  auto tw = as_vec3(twists);
  // Marks's B of the quadrant patch (docs/kernels.md's M, the same places: docs/marks.md), corners
  // C (pole, longitude 0), S (equator, longitude 0), E (pole, longitude 90), SE (equator, longitude
  // 90).
  const int C = 1 * n + 1, S = 21 * n + 1, E = 1 * n + 21, SE = 21 * n + 21;
  auto H = [&](int k) { return 20.0 * t.along_curves[k]; };
  auto V = [&](int k) { return 20.0 * t.along_stringers[k]; };
  auto T = [&](int k) { return 400.0 * Vec3(tw[k]); };
  const Vec3 marks[4][4] = {
      {p[C], p[S], V(C), V(S)},
      {p[E], p[SE], V(E), V(SE)},
      {H(C), H(S), T(C), T(S)},
      {H(E), H(SE), T(E), T(SE)},
  };
  // Coons's B (Marks's paper, "Results") for radius R, per coordinate.
  const double a = 4 * (std::sqrt(2.0) - 1);
  const double coons[3][4][4] = {
      {{0, 0, 0, 0}, {0, R, a * R, 0}, {0, a * R, a * a * R, 0}, {0, 0, 0, 0}},
      {{0, R, a * R, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, -a * R, -a * a * R, 0}},
      {{R, 0, 0, -a * R}, {R, 0, 0, -a * R}, {0, 0, 0, 0}, {0, 0, 0, 0}},
  };
  double worst_tangent = 0, worst_twist = 0;
  for (int k = 0; k < 3; ++k) {
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        const double ours = k == 0 ? marks[r][c].x : k == 1 ? marks[r][c].y : marks[r][c].z;
        const double theirs = coons[k][r][c];
        INFO("k=", k, " ", "r=", r, " ", "c=", c, " ", "ours=", ours, " ", "theirs=", theirs);
        if (theirs == 0) {
          CHECK(std::abs(ours) < 1e-9 * R);  // no element where none is expected
        } else if (std::abs(theirs) == R) {
          CHECK(ours == doctest::Approx(theirs).epsilon(1e-15));
        } else {
          const double error = std::abs(ours - theirs) / std::abs(theirs);
          (r >= 2 && c >= 2 ? worst_twist : worst_tangent) =
              std::max(r >= 2 && c >= 2 ? worst_twist : worst_tangent, error);
          CHECK(ours * theirs > 0);
        }
      }
    }
  }
  // The figures in closed form: the F-mesh tangent is the chord of 4.5 degrees (the shorter of
  // two equal chords), 20 x 2R sin(2.25 deg) = 157.04; the twist at the pole is R sin^2(4.5 deg),
  // x 400 = 246.2 (docs/kernels.md's reference figures).
  CHECK(V(C).y == doctest::Approx(40 * R * std::sin(step / 2)).epsilon(1e-13));
  CHECK(V(C).y == doctest::Approx(157.04).epsilon(1e-4));
  CHECK(T(C).x == doctest::Approx(400 * R * std::sin(step) * std::sin(step)).epsilon(1e-12));
  CHECK(T(C).x == doctest::Approx(246.23).epsilon(1e-4));
  CHECK(T(E).y == doctest::Approx(-T(C).x).epsilon(1e-12));
  // The report: 9/166 ~ 6 % for the tangents, 27/275 ~ 10 % for the twists (to the precision of
  // its table: the twist here is 28.3 below a^2 R = 274.5, 10.3 %).
  MESSAGE("sphere octant: tangents x 20 within ", 100 * worst_tangent, " %, twists x 400 within ",
          100 * worst_twist, " %");
  CHECK(worst_tangent < 0.06);
  CHECK(worst_twist < 0.105);
  CHECK(std::round(100 * worst_twist) <= 10);
}

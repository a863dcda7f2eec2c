// COONS and FIT through interpolate and refit (workspace/kernels/surface.h, coons.h, fit.h).
#include "workspace/kernels/surface.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <string>

#include "tests/kernels/helpers.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"
#include "workspace/kernels/processor.h"
#include "workspace/kernels/spline.h"

using namespace igds;
using igds::test::distance;
using igds::test::eval_patch;
using igds::test::Grid;
using igds::test::max_distance;
using igds::test::Random;
using igds::test::wavy_grid;

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

Surface run(const Grid& g, int intcu, int intst) {
  return interpolate({g.nocur, g.nostr, intcu, intst, &g.inppn, &g.inptg});
}

Vec3 intpn_at(const Array& intpn, std::size_t row, std::size_t col) {
  return as_vec3(intpn)[row * intpn.shape[1] + col];
}

void set_tangent(Array& inptg, std::size_t row, Vec3 t) {
  inptg.ravel[4 * row] = t.x, inptg.ravel[4 * row + 1] = t.y, inptg.ravel[4 * row + 2] = t.z;
}

std::string error_of(const SurfaceInput& in) {
  try {
    interpolate(in);
  } catch (const DataError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("the shapes of PATCHES and INTPN") {
  Grid g = wavy_grid(4, 6, 10);
  Surface s = run(g, 2, 3);
  CHECK(s.patches.shape == std::vector<std::size_t>{3, 5, 3, 4, 4});
  CHECK(s.intpn.shape == std::vector<std::size_t>{4 + 2 * 3, 6 + 3 * 5, 3});
  CHECK(s.intpn.size() == 10 * 21 * 3);
  Surface none = run(g, 0, 0);
  CHECK(none.intpn.shape == std::vector<std::size_t>{4, 6, 3});
}

TEST_CASE("every curve and stringer is clamped by its own INPTG rows") {
  Grid g = wavy_grid(5, 7, 28);
  auto pts = as_vec3(g.inppn);
  GridTangents t = grid_tangents(5, 7, pts, g.inptg);
  auto row_tangent = [&](int row) {
    const double* r = g.inptg.data() + 4 * row;
    return Vec3{r[0], r[1], r[2]};
  };
  auto row_point = [&](int row) { return int(g.inptg.ravel[4 * row + 3]); };
  for (int i = 0; i < 5; ++i) {
    // Rows 2i and 2i+1: curve i at place 1 and place NOSTR.
    CHECK(row_point(2 * i) == i * 7 + 1);
    CHECK(row_point(2 * i + 1) == i * 7 + 7);
    std::vector<Vec3> expected(7);
    spline_tangents(Vec3View(pts.subspan(i * 7, 7)), row_tangent(2 * i), row_tangent(2 * i + 1),
                    expected);
    for (int j = 0; j < 7; ++j) CHECK(t.along_curves[i * 7 + j] == expected[j]);
  }
  for (int j = 0; j < 7; ++j) {
    // Rows 2 NOCUR + 2j and + 1: stringer j at curve 1 and curve NOCUR.
    CHECK(row_point(10 + 2 * j) == j + 1);
    CHECK(row_point(10 + 2 * j + 1) == 4 * 7 + j + 1);
    std::vector<Vec3> column(5), expected(5);
    for (int i = 0; i < 5; ++i) column[i] = pts[i * 7 + j];
    spline_of(column, row_tangent(10 + 2 * j), row_tangent(10 + 2 * j + 1), expected);
    for (int i = 0; i < 5; ++i) CHECK(t.along_stringers[i * 7 + j] == expected[i]);
  }
}

TEST_CASE("patch edges coincide with the spline arcs of the curves and stringers") {
  Grid g = wavy_grid(5, 6, 11);
  auto pts = as_vec3(g.inppn);
  GridTangents t = grid_tangents(g.nocur, g.nostr, pts, g.inptg);
  Surface s = run(g, 1, 1);
  const int ns = g.nostr;
  for (int i = 0; i + 1 < g.nocur; ++i) {
    for (int j = 0; j + 1 < ns; ++j) {
      const double* m = s.patches.data() + 48 * (i * (ns - 1) + j);
      for (double w : {0.0, 0.1, 0.37, 0.5, 0.83, 1.0}) {
        for (int b = 0; b < 2; ++b) {
          // Curve i+b's arc j at u = w, and stringer j+b's arc i at v = w.
          int k0 = (i + b) * ns + j, k1 = k0 + 1;
          Vec3 curve =
              spline_arc_point(pts[k0], pts[k1], t.along_curves[k0], t.along_curves[k1], w);
          CHECK(distance(eval_patch(m, w, b), curve) < 1e-13);
          int s0 = i * ns + j + b, s1 = s0 + ns;
          Vec3 stringer =
              spline_arc_point(pts[s0], pts[s1], t.along_stringers[s0], t.along_stringers[s1], w);
          CHECK(distance(eval_patch(m, b, w), stringer) < 1e-13);
        }
      }
    }
  }
}

TEST_CASE("INTPN holds the patches evaluated at a/(INT+1) and the input points bit-exact") {
  Grid g = wavy_grid(4, 5, 12);
  g.inppn.ravel[7] += 1e7;  // a large offset on one point makes round-off visible
  const int intcu = 3, intst = 6;
  Surface s = run(g, intcu, intst);
  auto pts = as_vec3(g.inppn);
  for (int i = 0; i < g.nocur; ++i) {
    for (int j = 0; j < g.nostr; ++j) {
      Vec3 p = intpn_at(s.intpn, i * (intcu + 1), j * (intst + 1));
      const Vec3 q = pts[i * g.nostr + j];
      CHECK(std::memcmp(&p, &q, sizeof p) == 0);
    }
  }
  const std::size_t rows = s.intpn.shape[0], cols = s.intpn.shape[1];
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      std::size_t i = std::min<std::size_t>(r / (intcu + 1), g.nocur - 2);
      std::size_t j = std::min<std::size_t>(c / (intst + 1), g.nostr - 2);
      double v = double(r - i * (intcu + 1)) / (intcu + 1);
      double u = double(c - j * (intst + 1)) / (intst + 1);
      const double* m = s.patches.data() + 48 * (i * (g.nostr - 1) + j);
      CHECK(distance(intpn_at(s.intpn, r, c), eval_patch(m, u, v)) < 1e-8);
    }
  }
}

TEST_CASE("a grid made on the cores, in column chunks, by streaming stores: input points exact") {
  // 2098 columns (more than a chunk of 2048, which does not end on an input column) by 1201
  // rows: 60 MB of INTPN, made on the cores and written past the cache.
  Grid g = wavy_grid(301, 700, 5);
  g.inppn.ravel[3 * (150 * 700 + 683) + 1] += 1e7;  // an input point past the first chunk
  const int intcu = 3, intst = 2;
  Surface s = run(g, intcu, intst);
  REQUIRE(s.intpn.shape == std::vector<std::size_t>{1201, 2098, 3});
  auto pts = as_vec3(g.inppn);
  std::size_t exact = 0;
  for (int i = 0; i < g.nocur; ++i)
    for (int j = 0; j < g.nostr; ++j) {
      const Vec3 p = intpn_at(s.intpn, i * (intcu + 1), j * (intst + 1));
      const Vec3 q = pts[i * g.nostr + j];
      exact += std::memcmp(&p, &q, sizeof p) == 0;
    }
  CHECK(exact == std::size_t(g.nocur) * g.nostr);
  // Every point of an input curve's row, and of the rows beside it, is its patch's.
  for (std::size_t r : {0u, 1u, 599u, 600u, 601u, 1199u, 1200u})
    for (std::size_t c = 0; c < 2098; ++c) {
      const std::size_t i = std::min<std::size_t>(r / (intcu + 1), g.nocur - 2);
      const std::size_t j = std::min<std::size_t>(c / (intst + 1), g.nostr - 2);
      const double v = double(r - i * (intcu + 1)) / (intcu + 1);
      const double u = double(c - j * (intst + 1)) / (intst + 1);
      const double* m = s.patches.data() + 48 * (i * (g.nostr - 1) + j);
      if (!(distance(intpn_at(s.intpn, r, c), eval_patch(m, u, v)) < 1e-6)) {
        CAPTURE(r);
        CAPTURE(c);
        FAIL("a point is not its patch's");
      }
    }
}

TEST_CASE("a flat rectangular lattice interpolates to the uniform lattice") {
  const int nocur = 4, nostr = 5, intcu = 3, intst = 4;
  const double x0 = -3, y0 = 7, hx = 1.25, hy = 0.5;
  Array inppn({std::size_t(nocur * nostr), 3}), inptg({2 * (nocur + nostr), 4});
  auto pts = as_vec3(inppn);
  for (int i = 0; i < nocur; ++i)
    for (int j = 0; j < nostr; ++j) pts[i * nostr + j] = {x0 + j * hx, y0 + i * hy, 2};
  for (int r = 0; r < 2 * nocur; ++r) set_tangent(inptg, r, {1, 0, 0});
  for (int r = 2 * nocur; r < 2 * (nocur + nostr); ++r) set_tangent(inptg, r, {0, 1, 0});
  Surface s = interpolate({nocur, nostr, intcu, intst, &inppn, &inptg});
  for (std::size_t r = 0; r < s.intpn.shape[0]; ++r) {
    for (std::size_t c = 0; c < s.intpn.shape[1]; ++c) {
      Vec3 expected{x0 + c * hx / (intst + 1), y0 + r * hy / (intcu + 1), 2};
      CHECK(distance(intpn_at(s.intpn, r, c), expected) < 1e-13);
    }
  }
}

TEST_CASE("a translational surface S(x)+C(y) interpolates to spline(u)+spline(v)") {
  const int nocur = 5, nostr = 6, intcu = 4, intst = 3;
  Random rnd(13);
  std::vector<Vec3> s_pts(nostr), c_pts(nocur);
  double x = 0, y = 0;
  for (auto& p : s_pts) p = {x += rnd.uniform(0.5, 2), 0, std::sin(x)};
  for (auto& p : c_pts) p = {0, y += rnd.uniform(0.5, 2), 0.3 * y * y};
  Vec3 s_first = rnd.vec(-1, 1), s_last = rnd.vec(-1, 1);
  Vec3 c_first = rnd.vec(-1, 1), c_last = rnd.vec(-1, 1);
  Array inppn({std::size_t(nocur * nostr), 3}), inptg({2 * (nocur + nostr), 4});
  auto pts = as_vec3(inppn);
  for (int i = 0; i < nocur; ++i)
    for (int j = 0; j < nostr; ++j) pts[i * nostr + j] = s_pts[j] + c_pts[i];
  for (int i = 0; i < nocur; ++i) {
    set_tangent(inptg, 2 * i, s_first);
    set_tangent(inptg, 2 * i + 1, s_last);
  }
  for (int j = 0; j < nostr; ++j) {
    set_tangent(inptg, 2 * nocur + 2 * j, c_first);
    set_tangent(inptg, 2 * nocur + 2 * j + 1, c_last);
  }
  std::vector<Vec3> s_tg(nostr), c_tg(nocur);
  spline_of(s_pts, s_first, s_last, s_tg);
  spline_of(c_pts, c_first, c_last, c_tg);
  Surface s = interpolate({nocur, nostr, intcu, intst, &inppn, &inptg});
  for (std::size_t r = 0; r < s.intpn.shape[0]; ++r) {
    for (std::size_t c = 0; c < s.intpn.shape[1]; ++c) {
      std::size_t i = std::min<std::size_t>(r / (intcu + 1), nocur - 2);
      std::size_t j = std::min<std::size_t>(c / (intst + 1), nostr - 2);
      double v = double(r - i * (intcu + 1)) / (intcu + 1);
      double u = double(c - j * (intst + 1)) / (intst + 1);
      Vec3 expected = spline_arc_point(s_pts[j], s_pts[j + 1], s_tg[j], s_tg[j + 1], u) +
                      spline_arc_point(c_pts[i], c_pts[i + 1], c_tg[i], c_tg[i + 1], v);
      CHECK(distance(intpn_at(s.intpn, r, c), expected) < 1e-12);
    }
  }
}

TEST_CASE("translating, rotating and scaling the input transforms the grid the same way") {
  Grid g = wavy_grid(5, 4, 14);
  Surface s = run(g, 3, 2);
  const double angle = 0.7, scale = 37.5;
  const Vec3 shift{1e3, -250, 42};
  // A rotation about the axis (1, 2, 2)/3 (Rodrigues' formula).
  const Vec3 axis{1.0 / 3, 2.0 / 3, 2.0 / 3};
  auto rotate = [&](Vec3 v) {
    return std::cos(angle) * v + std::sin(angle) * cross(axis, v) +
           ((1 - std::cos(angle)) * dot(axis, v)) * axis;
  };
  Grid h = g;
  for (auto p : as_vec3(h.inppn)) p = scale * rotate(p) + shift;
  // Tangents per unit of chord length turn with the surface and do not change with its scale.
  for (std::size_t r = 0; r < h.inptg.shape[0]; ++r) {
    double* t = h.inptg.data() + 4 * r;
    Vec3 v = rotate({t[0], t[1], t[2]});
    t[0] = v.x, t[1] = v.y, t[2] = v.z;
  }
  Surface moved = run(h, 3, 2);
  Array expected = s.intpn;
  for (auto p : as_vec3(expected)) p = scale * rotate(p) + shift;
  CHECK(max_distance(moved.intpn, expected) < 1e-11 * scale * 10);
}

TEST_CASE("refit gives the grid that interpolate gives for the new INTCU and INTST") {
  Grid g = wavy_grid(6, 5, 15);
  Surface coarse = run(g, 1, 2);
  Surface fine = run(g, 4, 0);
  Array refitted = refit({g.nocur, g.nostr, 4, 0, &g.inppn, nullptr}, coarse.patches);
  CHECK(refitted == fine.intpn);
  CHECK(coarse.patches == fine.patches);
}

TEST_CASE("large grids are computed in parallel to the same result") {
  Grid g = wavy_grid(30, 40, 16);
  Surface s = run(g, 20, 12);  // 30+20*29 = 610 by 40+12*39 = 508: over the threading threshold
  CHECK(s.intpn.shape[0] * s.intpn.shape[1] > 300000);
  const std::size_t rows = s.intpn.shape[0], cols = s.intpn.shape[1];
  for (std::size_t r = 0; r < rows; r += 37) {
    for (std::size_t c = 0; c < cols; c += 11) {
      std::size_t i = std::min<std::size_t>(r / 21, g.nocur - 2);
      std::size_t j = std::min<std::size_t>(c / 13, g.nostr - 2);
      double v = double(r - i * 21) / 21, u = double(c - j * 13) / 13;
      const double* m = s.patches.data() + 48 * (i * (g.nostr - 1) + j);
      CHECK(distance(intpn_at(s.intpn, r, c), eval_patch(m, u, v)) < 1e-12);
    }
  }
  // The last row and column (u = 1, v = 1 of the last patches) are the input points.
  CHECK(intpn_at(s.intpn, rows - 1, cols - 1) == as_vec3(g.inppn).back());
}

TEST_CASE("large offsets cost no precision: the grid is computed about a local origin") {
  Grid g = wavy_grid(4, 4, 17);
  Surface s = run(g, 5, 5);
  for (double offset : {3e9, 1e15}) {
    Grid far = g;
    for (auto p : as_vec3(far.inppn)) p = p + Vec3{offset, -offset, offset};
    Surface t = run(far, 5, 5);
    // Every coordinate is within one unit in the last place of the offset grid's own numbers:
    // the rounding of the final sum, nothing accumulated from the offset.
    auto near = as_vec3(std::as_const(s.intpn)), moved = as_vec3(std::as_const(t.intpn));
    double worst = 0;
    for (std::size_t k = 0; k < near.size(); ++k) {
      const Vec3 a = near[k], b = moved[k];
      const double expected[3] = {a.x + offset, a.y - offset, a.z + offset};
      const double got[3] = {b.x, b.y, b.z};
      for (int c = 0; c < 3; ++c) {
        const double ulp = std::nextafter(std::abs(expected[c]), INFINITY) - std::abs(expected[c]);
        worst = std::max(worst, std::abs(got[c] - expected[c]) / ulp);
      }
    }
    CAPTURE(offset);
    CHECK(worst <= 1.0);
  }
}

TEST_CASE("equal consecutive points: a zero-length arc evaluates to its point") {
  Grid g = wavy_grid(4, 5, 18);
  auto pts = as_vec3(g.inppn);
  // Curves 2 and 3 (1-based) meet at place 4: stringer 4 has a zero-length arc.
  pts[2 * 5 + 3] = pts[1 * 5 + 3];
  // Curve 4 has two equal consecutive points.
  pts[3 * 5 + 2] = pts[3 * 5 + 1];
  const int intcu = 3, intst = 3;
  Surface s = run(g, intcu, intst);
  for (double v : s.intpn.ravel) REQUIRE(std::isfinite(v));
  for (int b = 0; b <= intcu + 1; ++b) {
    CHECK(distance(intpn_at(s.intpn, 1 * (intcu + 1) + b, 3 * (intst + 1)), pts[1 * 5 + 3]) <
          1e-13);
  }
  for (int a = 0; a <= intst + 1; ++a) {
    CHECK(distance(intpn_at(s.intpn, 3 * (intcu + 1), 1 * (intst + 1) + a), pts[3 * 5 + 1]) <
          1e-13);
  }
  // The duplicate takes the tangent of its merged point.
  GridTangents t = grid_tangents(g.nocur, g.nostr, pts, g.inptg);
  CHECK(t.along_curves[3 * 5 + 2] == t.along_curves[3 * 5 + 1]);
  CHECK(t.along_stringers[2 * 5 + 3] == t.along_stringers[1 * 5 + 3]);
}

TEST_CASE("a sphere octant with a pole: the all-coincident line gets zero tangents") {
  // Curves are meridians from the equator (place 1) to the pole (place NOSTR), so the last
  // stringer is the pole itself, given twice as many non-zero tangents as the user might type.
  const int nocur = 6, nostr = 7, intcu = 4, intst = 4;
  const double radius = 100, quarter = std::numbers::pi / 2;
  Array inppn({std::size_t(nocur * nostr), 3}), inptg({2 * (nocur + nostr), 4});
  auto pts = as_vec3(inppn);
  for (int i = 0; i < nocur; ++i) {
    double lon = quarter * i / (nocur - 1);
    for (int j = 0; j < nostr; ++j) {
      double lat = quarter * j / (nostr - 1);
      pts[i * nostr + j] = j + 1 == nostr
                               ? Vec3{0, 0, radius}
                               : radius * Vec3{std::cos(lat) * std::cos(lon),
                                               std::cos(lat) * std::sin(lon), std::sin(lat)};
    }
    set_tangent(inptg, 2 * i, {0, 0, 1});
    set_tangent(inptg, 2 * i + 1, {-std::cos(lon), -std::sin(lon), 0});
  }
  for (int j = 0; j < nostr; ++j) {
    set_tangent(inptg, 2 * nocur + 2 * j, {0, 1, 0});
    set_tangent(inptg, 2 * nocur + 2 * j + 1, {-1, 0, 0});
  }
  GridTangents t = grid_tangents(nocur, nostr, pts, inptg);
  for (int i = 0; i < nocur; ++i) CHECK(t.along_stringers[i * nostr + nostr - 1] == Vec3{});
  Surface s = interpolate({nocur, nostr, intcu, intst, &inppn, &inptg});
  const std::size_t cols = s.intpn.shape[1];
  for (std::size_t r = 0; r < s.intpn.shape[0]; ++r) {
    // The pole column stays the pole.
    CHECK(distance(intpn_at(s.intpn, r, cols - 1), {0, 0, radius}) < 1e-12);
    for (std::size_t c = 0; c < cols; ++c) {
      Vec3 p = intpn_at(s.intpn, r, c);
      REQUIRE(std::isfinite(p.x + p.y + p.z));
      CHECK(std::abs(norm(p) - radius) < 0.01 * radius);
    }
  }
}

TEST_CASE("non-finite points and tangents are refused, naming the point") {
  Grid g = wavy_grid(3, 4, 19);
  SurfaceInput in{3, 4, 2, 2, &g.inppn, &g.inptg};
  g.inppn.ravel[3 * 6 + 1] = NAN;
  CHECK(error_of(in) == "point 7 is not finite");
  g.inppn.ravel[3 * 6 + 1] = 0;
  g.inppn.ravel[3 * 11 + 2] = -INFINITY;
  CHECK(error_of(in) == "point 12 is not finite");
  g.inppn.ravel[3 * 11 + 2] = 0;
  CHECK(error_of(in) == "(accepted)");
  // Curve 2's tangent at place NOSTR is INPTG row 4 (1-based): point 8.
  g.inptg.ravel[4 * 3] = INFINITY;
  CHECK(error_of(in) == "the tangent at point 8 is not finite");
  g.inptg.ravel[4 * 3] = 0;
  // Stringer 3's tangent at curve NOCUR is row 2*3 + 2*2 + 2 = 12: point 2*4 + 3 = 11.
  g.inptg.ravel[4 * 11 + 1] = NAN;
  CHECK(error_of(in) == "the tangent at point 11 is not finite");
  g.inptg.ravel[4 * 11 + 1] = 0;
  // Stringer 1's tangent at curve 1 (row 7): point 1, a corner.
  g.inptg.ravel[4 * 6 + 2] = NAN;
  CHECK(error_of(in) == "the tangent at point 1 is not finite");
}

TEST_CASE("sizes and shapes that do not match are refused") {
  Grid g = wavy_grid(3, 4, 20);
  CHECK(error_of({1, 1, 0, 0, &g.inppn, &g.inptg}) == "the grid is too small");
  CHECK(error_of({0, 4, 0, 0, &g.inppn, &g.inptg}) == "the grid is too small");
  CHECK(error_of({3, 4, -1, 0, &g.inppn, &g.inptg}) == "INTCU or INTST is negative");
  CHECK(error_of({3, 4, 0, 0, nullptr, &g.inptg}) == "INPPN is missing");
  CHECK(error_of({3, 4, 0, 0, &g.inppn, nullptr}) == "INPTG is missing");
  CHECK(error_of({4, 4, 0, 0, &g.inppn, &g.inptg}) == "INPPN has shape 12 3, not 16 3");
  CHECK(error_of({3, 4, 0, 0, &g.inptg, &g.inptg}) == "INPPN has shape 14 4, not 12 3");
  CHECK(error_of({3, 4, 0, 0, &g.inppn, &g.inppn}) == "INPTG has shape 12 3, not 14 4");
  CHECK(error_of({3, 4, 100000, 100000, &g.inppn, &g.inptg}) ==
        "60001700012 points, more than 4000000");
  CHECK(error_of({3, 4, 2147483647, 2147483647, &g.inppn, &g.inptg}) ==
        "27670116121301745664 points, more than 4000000");
}

TEST_CASE("refit refuses patches of the wrong shape or with non-finite numbers") {
  Grid g = wavy_grid(3, 4, 21);
  Surface s = run(g, 1, 1);
  auto refit_error = [&](const Array& patches) -> std::string {
    try {
      refit({3, 4, 2, 2, &g.inppn, nullptr}, patches);
    } catch (const DataError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  CHECK(refit_error(s.patches) == "(accepted)");
  CHECK(refit_error(Array({2, 2, 3, 4, 4})) == "PATCHES has shape 2 2 3 4 4, not 2 3 3 4 4");
  CHECK(refit_error(Array{}) == "PATCHES has shape , not 2 3 3 4 4");
  Array bad = s.patches;
  bad.ravel[48 * 4 + 17] = NAN;
  CHECK(refit_error(bad) == "patch 5 is not finite");
  g.inppn.ravel[0] = INFINITY;
  CHECK(refit_error(s.patches) == "point 1 is not finite");
}

TEST_CASE("very wide patches and grids beyond the cache take the chunked, streaming paths") {
  // 3 x 2 input points with 3000 stringers inserted: one patch spans several column chunks.
  Grid narrow = wavy_grid(3, 2, 22);
  Surface s = run(narrow, 2, 3000);
  CHECK(s.intpn.shape == std::vector<std::size_t>{7, 3002, 3});
  for (std::size_t r = 0; r < 7; ++r) {
    for (std::size_t c = 0; c < 3002; c += 7) {
      std::size_t i = std::min<std::size_t>(r / 3, 1);
      const double* m = s.patches.data() + 48 * i;
      CHECK(distance(intpn_at(s.intpn, r, c), eval_patch(m, c / 3001.0, (r - 3.0 * i) / 3)) <
            1e-12);
    }
  }
  // 1190 x 1600 points (46 MB): written with streaming stores by several threads.
  Grid g = wavy_grid(30, 40, 23);
  Surface big = run(g, 40, 40);
  CHECK(big.intpn.size() > (std::size_t(1) << 22));
  Random rnd(24);
  for (int sample = 0; sample < 2000; ++sample) {
    std::size_t r = std::size_t(rnd.uniform(0, 1190)), c = std::size_t(rnd.uniform(0, 1600));
    std::size_t i = std::min<std::size_t>(r / 41, 28), j = std::min<std::size_t>(c / 41, 38);
    const double* m = big.patches.data() + 48 * (i * 39 + j);
    CHECK(distance(intpn_at(big.intpn, r, c),
                   eval_patch(m, (c - 41.0 * j) / 41, (r - 41.0 * i) / 41)) < 1e-12);
  }
  for (std::size_t c = 0; c < 1600; ++c) REQUIRE(std::isfinite(intpn_at(big.intpn, 1189, c).x));
}

TEST_CASE("the baseline and the vector code of FIT give the same grids") {
  Grid g = wavy_grid(30, 40, 27);
  for (int density : {3, 40}) {  // below and above the size written with streaming stores
    Surface best = run(g, density, density);
    use_kernel_code(KernelCode::baseline);
    Surface baseline = run(g, density, density);
    use_kernel_code(KernelCode::best);
    CAPTURE(density);
    CHECK(max_distance(best.intpn, baseline.intpn) < 1e-12);
    CHECK(best.patches == baseline.patches);
    // Both write every number: no zero left behind where a stretch was skipped.
    for (std::size_t k = 1; k < baseline.intpn.size(); k += 997)
      CHECK(baseline.intpn.ravel[k] != 0);
  }
}

TEST_CASE("interpolate_into and refit_into reuse the arrays they are given") {
  Grid g = wavy_grid(8, 9, 25);
  SurfaceInput in{8, 9, 5, 6, &g.inppn, &g.inptg};
  Surface expected = interpolate(in);
  Surface out;
  CHECK_FALSE(interpolate_into(in, out));
  CHECK(out == expected);
  const double* memory = out.intpn.data();
  CHECK_FALSE(interpolate_into(in, out));
  CHECK(out.intpn.data() == memory);
  CHECK(out == expected);
  // A smaller grid fits in the same memory; a much larger one gets new memory.
  CHECK_FALSE(interpolate_into({8, 9, 4, 6, &g.inppn, &g.inptg}, out));
  CHECK(out.intpn.data() == memory);
  CHECK(out.intpn == interpolate({8, 9, 4, 6, &g.inppn, &g.inptg}).intpn);
  CHECK_FALSE(refit_into({8, 9, 20, 20, &g.inppn, nullptr}, out.patches, out.intpn));
  CHECK(out.intpn == refit({8, 9, 20, 20, &g.inppn, nullptr}, out.patches));
  // Bad data leaves the output as it was.
  Surface before = out;
  g.inppn.ravel[5] = NAN;
  CHECK_THROWS_AS((void)interpolate_into(in, out), DataError);
  CHECK_THROWS_AS((void)refit_into(in, out.patches, out.intpn), DataError);
  CHECK(out == before);
}

TEST_CASE("an output that is also an input is computed apart") {
  Grid g = wavy_grid(4, 4, 26);
  Surface s = run(g, 2, 2);
  Array patches = s.patches;
  CHECK_FALSE(refit_into({4, 4, 3, 3, &g.inppn, nullptr}, patches, patches));
  CHECK(patches == refit({4, 4, 3, 3, &g.inppn, nullptr}, s.patches));
  Grid h = g;
  Surface aliased;
  SurfaceInput in{4, 4, 2, 2, &aliased.intpn, &h.inptg};
  aliased.intpn = h.inppn;
  CHECK_FALSE(interpolate_into(in, aliased));
  CHECK(aliased == s);
}

TEST_CASE("a single curve or stringer is the spline of its points, without patches") {
  for (bool curve : {true, false}) {
    const int n = 4, inserted = 2;
    Grid g = wavy_grid(curve ? 1 : n, curve ? n : 1, 40);
    Surface s = run(g, curve ? 7 : inserted, curve ? inserted : 7);  // the other density is moot
    const std::size_t count = n + inserted * (n - 1);
    CHECK(s.intpn.shape ==
          (curve ? std::vector<std::size_t>{1, count, 3} : std::vector<std::size_t>{count, 1, 3}));
    CHECK(s.patches.size() == 0);
    CHECK(s.patches.shape ==
          std::vector<std::size_t>{curve ? 0u : n - 1u, curve ? n - 1u : 0u, 3, 4, 4});
    // The line's end tangents: INPTG rows 0 and 1 for a curve, 2 NOCUR and 2 NOCUR + 1 for a
    // stringer.
    const std::size_t row = curve ? 0 : 2 * n;
    const double* t = g.inptg.data();
    const Vec3 first{t[4 * row], t[4 * row + 1], t[4 * row + 2]};
    const Vec3 last{t[4 * row + 4], t[4 * row + 5], t[4 * row + 6]};
    std::vector<Vec3> tangents(n);
    spline_tangents(as_vec3(std::as_const(g.inppn)), first, last, tangents);
    const auto pts = as_vec3(std::as_const(g.inppn));
    const auto grid = as_vec3(std::as_const(s.intpn));
    for (int k = 0; k < n; ++k) CHECK(Vec3(grid[std::size_t(k) * (inserted + 1)]) == pts[k]);
    for (int k = 0; k + 1 < n; ++k)
      for (int a = 1; a <= inserted; ++a) {
        const Vec3 expected = spline_arc_point(pts[k], pts[k + 1], tangents[k], tangents[k + 1],
                                               double(a) / (inserted + 1));
        CHECK(distance(grid[std::size_t(k) * (inserted + 1) + a], expected) < 1e-12);
      }
    // CHANGE GRID on a line makes the grid again from the points.
    Array again =
        refit({g.nocur, g.nostr, curve ? 0 : 1, curve ? 1 : 0, &g.inppn, &g.inptg}, s.patches);
    CHECK(again.shape[curve ? 1 : 0] == std::size_t(n + (n - 1)));
  }
}

TEST_CASE("first_not_finite finds the first number that is not finite, in large arrays too") {
  // Large enough to be read on several cores: the first of the whole array, not of a slice.
  for (const std::size_t n :
       {std::size_t(0), std::size_t(5), std::size_t(1) << 20, (std::size_t(3) << 20) + 7}) {
    CAPTURE(n);
    std::vector<double> v(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = (k % 3 == 0 ? -1.0 : 1.0) * double(k % 1000) * 1e300;
    CHECK(first_not_finite(v.data(), n) == n);
    if (n == 0) continue;
    for (const std::size_t at : {std::size_t(0), n / 3, n / 2, n / 2 + 1, n - 1}) {
      std::vector<double> w = v;
      w[at] = std::nan("");
      if (at + 5 < n) w[at + 5] = HUGE_VAL;
      if (at > 0) w[n - 1] = -HUGE_VAL;
      CHECK(first_not_finite(w.data(), n) == at);
    }
  }
}

TEST_CASE("finite_points finds the first number that is not finite, else the points' box") {
  // Large enough to be read on several cores; each side of the box reached in another part.
  for (const std::size_t n :
       {std::size_t(1), std::size_t(5), std::size_t(1) << 19, (std::size_t(3) << 19) + 7}) {
    CAPTURE(n);
    std::vector<double> v(2 * n);
    for (std::size_t k = 0; k < 2 * n; ++k) v[k] = (k % 3 == 0 ? -1.0 : 1.0) * double(k % 1000);
    v[0] = -5e300, v[2 * n - 1] = 7e300;
    if (n > 2) v[2 * (n / 2) + 1] = -3e300, v[2 * (n - 2)] = 4e300;
    const FinitePoints all = finite_points(v.data(), n);
    CHECK(all.not_finite == 2 * n);
    CHECK(all.box == test::box_of_points(v.data(), n));
    for (const std::size_t at : {std::size_t(0), n, 2 * n / 3, 2 * n - 1}) {
      std::vector<double> w = v;
      w[at] = std::nan("");
      if (at + 5 < 2 * n) w[at + 5] = HUGE_VAL;
      if (at > 0) w[2 * n - 1] = -HUGE_VAL;
      CHECK(finite_points(w.data(), n).not_finite == at);
    }
  }
  CHECK(finite_points(nullptr, 0).not_finite == 0);
}

namespace {

// The report of a second reading of every number of `s`: what the kernels must find as they make
// them.
std::optional<DataError> read_again(const Surface& s) {
  if (const std::size_t k = first_not_finite(s.patches.data(), s.patches.size());
      k < s.patches.size()) {
    DataError e(DataError::Problem::patch_not_finite);
    e.number = k / 48 + 1;
    return e;
  }
  if (const std::size_t k = first_not_finite(s.intpn.data(), s.intpn.size()); k < s.intpn.size()) {
    DataError e(DataError::Problem::grid_point_not_finite);
    e.number = k / 3 / s.intpn.shape[1] + 1;
    e.column = k / 3 % s.intpn.shape[1] + 1;
    return e;
  }
  return std::nullopt;
}

std::string said(const std::optional<DataError>& e) {
  return e ? e->what() : "finite";
}

}  // namespace

TEST_CASE("COONS and FIT find the first number that is not finite as they make it") {
  // 30 inserted: a grid of 4.4 M numbers, made on every core with streaming stores; 2: one core.
  for (const int density : {2, 30}) {
    for (const KernelCode code : {KernelCode::best, KernelCode::baseline}) {
      CAPTURE(density);
      CAPTURE(code == KernelCode::best);
      use_kernel_code(code);
      const Grid g = wavy_grid(40, 40, 31);
      const SurfaceInput in{40, 40, density, density, &g.inppn, &g.inptg};
      Surface s;
      CHECK(said(interpolate_into(in, s)) == "finite");
      CHECK(said(read_again(s)) == "finite");
      // PATCHES not kept: each row made as FIT comes to it, the same grid bit for bit; COONS
      // alone makes the same PATCHES.
      Surface dropped;
      dropped.patches = s.patches;
      CHECK(said(interpolate_into(in, dropped, PatchesOut::dropped)) == "finite");
      CHECK(dropped.patches.shape.empty());
      CHECK(std::memcmp(dropped.intpn.data(), s.intpn.data(), s.intpn.size() * sizeof(double)) ==
            0);
      CHECK(dropped.intpn.shape == s.intpn.shape);
      CHECK(surface_patches(in) == s.patches);

      // Finite patches so large that the grid overflows, in two parts of the rows: the first.
      Array patches = s.patches;
      for (const std::size_t patch : {std::size_t(33 * 39 + 20), std::size_t(6 * 39 + 30)})
        for (std::size_t k = 0; k < 48; ++k) patches.ravel[48 * patch + k] = 1.5e308;
      Array intpn;
      const std::size_t k = fit(40, 40, density, density, patches, as_vec3(g.inppn), intpn);
      CHECK(k == first_not_finite(intpn.data(), intpn.size()));
      CHECK(k < intpn.size());
      const auto grid = refit_into(in, patches, intpn);
      REQUIRE(grid);
      CHECK(grid->problem == DataError::Problem::grid_point_not_finite);
      CHECK(said(grid) == said(read_again({patches, intpn})));
      CHECK(grid->number > std::size_t(6 * (density + 1)));

      // Tangents of 1E308 at the borders: the patches overflow, the first named.
      Grid huge = g;
      for (const std::size_t row : {std::size_t(70), std::size_t(2 * 40 + 12)})
        set_tangent(huge.inptg, row, {1e308, -1e308, 1e308});
      const auto patch = interpolate_into({40, 40, density, density, &huge.inppn, &huge.inptg}, s);
      REQUIRE(patch);
      CHECK(patch->problem == DataError::Problem::patch_not_finite);
      CHECK(said(patch) == said(read_again(s)));
      // Not kept, the same patch is named: the least of the rows the threads made.
      const auto unkept = interpolate_into({40, 40, density, density, &huge.inppn, &huge.inptg},
                                           dropped, PatchesOut::dropped);
      REQUIRE(unkept);
      CHECK(said(unkept) == said(patch));
    }
  }
  use_kernel_code(KernelCode::best);
}

TEST_CASE("a single curve or stringer keeps its empty PATCHES when patches are not kept") {
  const Grid g = wavy_grid(1, 6, 5);
  const SurfaceInput in{1, 6, 0, 3, &g.inppn, &g.inptg};
  Surface kept, dropped;
  CHECK(!interpolate_into(in, kept));
  CHECK(!interpolate_into(in, dropped, PatchesOut::dropped));
  CHECK(dropped == kept);
  CHECK(dropped.patches.shape == std::vector<std::size_t>{0, 5, 3, 4, 4});
  CHECK(surface_patches(in) == kept.patches);
}

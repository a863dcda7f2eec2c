// An IGDS surface as exact curves (workspace/exchange/surface_curves.h): Bézier spans through
// INTPN, the Bézier net of the patches, the input curves as C2 B-splines, and the input points,
// border and tangents beside them; the records of a large IGES file written from them.
#include "workspace/exchange/surface_curves.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "tests/workspace/exchange_support.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/step.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"

namespace igds::test::exchange {

namespace {

Vec3 grid_point(const Array& intpn, std::size_t cols, std::size_t row, std::size_t col) {
  return Vec3::load(intpn.data() + 3 * (row * cols + col));
}

// A point of a clamped cubic B-spline (knots expanded by multiplicity), by de Boor's algorithm.
Vec3 de_boor(const std::vector<double>& knots, const std::vector<Vec3>& controls, double t) {
  std::size_t k = 3;
  while (k + 1 < controls.size() && t >= knots[k + 1]) ++k;
  Vec3 d[4];
  for (int j = 0; j < 4; ++j) d[j] = controls[k - 3 + std::size_t(j)];
  for (int r = 1; r <= 3; ++r) {
    for (int j = 3; j >= r; --j) {
      const std::size_t i = k - 3 + std::size_t(j);
      const double a = (t - knots[i]) / (knots[i + 4 - std::size_t(r)] - knots[i]);
      d[j] = (1 - a) * d[j - 1] + a * d[j];
    }
  }
  return d[3];
}

std::vector<double> expanded(const CubicBspline& c) {
  std::vector<double> out;
  for (std::size_t k = 0; k < c.knots.size(); ++k)
    out.insert(out.end(), std::size_t(c.multiplicities[k]), c.knots[k]);
  return out;
}

}  // namespace

TEST_CASE("every curve and stringer of the drawing passes through INTPN at its parameters") {
  for (const auto& shape :
       std::vector<std::array<int, 4>>{{5, 4, 2, 2}, {7, 6, 3, 1}, {3, 9, 0, 4}, {2, 2, 5, 0}}) {
    const int nc = shape[0], ns = shape[1], ic = shape[2], is = shape[3];
    CAPTURE(nc);
    CAPTURE(ns);
    const TestSurface t = test_surface(nc, ns, ic, is);
    const GridShape g = intpn_shape(nc, ns, ic, is);
    const Drawing3 d = surface_curves(t.input, t.surface);
    const double tolerance = 1e-12 * largest_coordinate(t.surface.intpn);
    std::size_t curves = 0, stringers = 0;
    double worst = 0;
    for (const auto& item : d.items()) {
      if (item.id.role != Role::curve && item.id.role != Role::stringer) continue;
      REQUIRE(item.kind == Drawing3::Kind::curve);
      CHECK(item.degree == 3);
      CHECK(d.weights(item).empty());
      CHECK(item.style == Style{});
      const bool curve = item.id.role == Role::curve;
      (curve ? curves : stringers) += 1;
      const std::size_t line = std::size_t(item.id.index) - 1;  // INTPN row or column
      const std::size_t spans = curve ? std::size_t(ns) - 1 : std::size_t(nc) - 1;
      const std::size_t between = curve ? std::size_t(is) : std::size_t(ic);
      const auto points = d.points(item);
      REQUIRE(points.size() == 3 * spans + 1);
      for (std::size_t s = 0; s < spans; ++s) {
        const Vec3 c[4] = {points[3 * s], points[3 * s + 1], points[3 * s + 2], points[3 * s + 3]};
        for (std::size_t a = 0; a <= between + 1; ++a) {
          const std::size_t along = s * (between + 1) + a;
          const Vec3 expected = curve ? grid_point(t.surface.intpn, g.cols, line, along)
                                      : grid_point(t.surface.intpn, g.cols, along, line);
          const Vec3 got = bezier3(c, double(a) / double(between + 1));
          worst = std::max(worst, norm(got - expected));
        }
      }
    }
    CHECK(curves == g.rows);
    CHECK(stringers == g.cols);
    CHECK(worst <= tolerance);
  }
}

TEST_CASE("the Bézier net holds the input points bit-exactly and evaluates to INTPN") {
  const TestSurface t = test_surface(6, 5, 3, 2);
  const BezierNet net = surface_net(t.input, t.surface.patches);
  REQUIRE(net.rows == 16);
  REQUIRE(net.cols == 13);
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 5; ++j)
      CHECK(std::memcmp(&net.xyz[3 * (3 * i * net.cols + 3 * j)], t.inppn.data() + 3 * (i * 5 + j),
                        3 * sizeof(double)) == 0);
  // Neighbouring patches share their borders bit for bit: patch j's row P(1,.), Pv(1,.) is
  // patch j+1's row P(0,.), Pv(0,.), and likewise down the columns.
  const double* m = t.surface.patches.data();
  for (std::size_t i = 0; i < 5; ++i) {
    for (std::size_t j = 0; j < 4; ++j) {
      const double* here = m + (i * 4 + j) * 48;
      for (int k = 0; k < 3; ++k) {
        if (j + 1 < 4) {
          const double* right = m + (i * 4 + j + 1) * 48;
          CHECK(std::memcmp(here + 16 * k + 4, right + 16 * k, 4 * sizeof(double)) == 0);
        }
        if (i + 1 < 5) {
          const double* below = m + ((i + 1) * 4 + j) * 48;
          for (int r = 0; r < 4; ++r)
            CHECK(std::memcmp(here + 16 * k + 4 * r + 1, below + 16 * k + 4 * r, sizeof(double)) ==
                  0);
        }
      }
    }
  }
  // Tensor-product Bézier evaluation of every patch at the INTPN parameters.
  const GridShape g = intpn_shape(6, 5, 3, 2);
  double worst = 0;
  for (std::size_t row = 0; row < g.rows; ++row) {
    const std::size_t i = std::min<std::size_t>(row / 4, 4);
    const double v = double(row - 4 * i) / 4;
    for (std::size_t col = 0; col < g.cols; ++col) {
      const std::size_t j = std::min<std::size_t>(col / 3, 3);
      const double u = double(col - 3 * j) / 3;
      Vec3 along_v[4];
      for (std::size_t b = 0; b < 4; ++b) {
        const Vec3 c[4] = {net.at(3 * i + b, 3 * j), net.at(3 * i + b, 3 * j + 1),
                           net.at(3 * i + b, 3 * j + 2), net.at(3 * i + b, 3 * j + 3)};
        along_v[b] = bezier3(c, u);
      }
      worst = std::max(worst,
                       norm(bezier3(along_v, v) - grid_point(t.surface.intpn, g.cols, row, col)));
    }
  }
  CHECK(worst <= 1e-12 * largest_coordinate(t.surface.intpn));
}

TEST_CASE(
    "the Bézier net of a surface large enough to be made on the cores: every patch's controls") {
  // 298 x 298 controls: more numbers than parallel.h's threads_for makes on one thread.
  const TestSurface t = test_surface(100, 100, 0, 0);
  const BezierNet net = surface_net(t.input, t.surface.patches);
  REQUIRE(net.xyz.size() >= (std::size_t(1) << 18));
  // Each patch's Bézier controls from its Hermite form (P, P + D/3, P - D/3, P along u, then
  // along v), where its neighbours' (the same bits) did not take their place.
  std::size_t wrong = 0;
  double largest = 0;
  for (std::size_t i = 0; i < 99; ++i)
    for (std::size_t j = 0; j < 99; ++j)
      for (std::size_t k = 0; k < 3; ++k) {
        const double* m = t.surface.patches.data() + (i * 99 + j) * 48 + 16 * k;
        for (std::size_t a = 0; a < 4; ++a) {
          const double p0 = a == 0   ? m[0]
                            : a == 1 ? m[0] + m[8] / 3
                            : a == 2 ? m[4] - m[12] / 3
                                     : m[4];
          auto at = [&](std::size_t c) {
            return a == 0   ? m[c]
                   : a == 1 ? m[c] + m[8 + c] / 3
                   : a == 2 ? m[4 + c] - m[12 + c] / 3
                            : m[4 + c];
          };
          const double b[4] = {p0, p0 + at(2) / 3, at(1) - at(3) / 3, at(1)};
          for (std::size_t v = 0; v < 4; ++v) {
            wrong += net.xyz[3 * ((3 * i + v) * net.cols + 3 * j + a) + k] != b[v];
            largest = std::max(largest, std::abs(b[v]));
          }
        }
      }
  CHECK(wrong == 0);
  CHECK(net.largest == largest);
  // The curves' and stringers' B-splines, made on the cores, are those made one by one.
  const std::vector<std::optional<CubicBspline>> splines = input_bsplines(net);
  REQUIRE(splines.size() == 200);
  for (std::size_t k = 0; k < 200; ++k) {
    const auto c = k < 100 ? input_curve_bspline(net, k) : input_stringer_bspline(net, k - 100);
    REQUIRE(c);
    REQUIRE(splines[k]);
    wrong += splines[k]->controls != c->controls || splines[k]->knots != c->knots ||
             splines[k]->multiplicities != c->multiplicities;
  }
  CHECK(wrong == 0);
  // A control that is not finite makes the largest magnitude infinite.
  Array patches = t.surface.patches;
  patches.ravel[48 * 5000 + 20] = NAN;
  CHECK(std::isinf(surface_net(t.input, patches).largest));
}

TEST_CASE("the drawing's input curves are the net's rows, bit for bit") {
  const TestSurface t = golden_surface();
  const BezierNet net = surface_net(t.input, t.surface.patches);
  const Drawing3 d = surface_curves(t.input, t.surface);
  for (const auto& item : d.items()) {
    if (item.id.role != Role::curve || (item.id.index - 1) % 3 != 0) continue;
    const std::size_t row = std::size_t(item.id.index - 1);  // input curve i is row 3i
    const auto points = d.points(item);
    REQUIRE(points.size() == net.cols);
    for (std::size_t k = 0; k < points.size(); ++k) CHECK(Vec3(points[k]) == net.at(row, k));
  }
}

TEST_CASE("input curves and stringers as C2 B-splines in the running chord length") {
  const TestSurface t = test_surface(5, 7, 0, 0);
  const BezierNet net = surface_net(t.input, t.surface.patches);
  const double tolerance = 1e-12 * largest_coordinate(t.inppn);
  for (std::size_t i = 0; i < 5; ++i) {
    const auto c = input_curve_bspline(net, i);
    REQUIRE(c);
    REQUIRE(c->knots.size() == 7);
    CHECK(c->controls.size() == 9);
    CHECK(c->multiplicities == std::vector<int>{4, 1, 1, 1, 1, 1, 4});
    const std::vector<double> knots = expanded(*c);
    double t_k = 0;
    for (std::size_t k = 0; k < 7; ++k) {
      const Vec3 p = Vec3::load(t.inppn.data() + 3 * (i * 7 + k));
      CHECK(std::abs(c->knots[k] - t_k) <= 1e-12 * t_k);
      CHECK(norm(de_boor(knots, c->controls, c->knots[k]) - p) <= tolerance);
      if (k + 1 < 7) {
        const Vec3 q = Vec3::load(t.inppn.data() + 3 * (i * 7 + k + 1));
        // The middle of each span is the Bézier span's middle: the same curve.
        const Vec3 span[4] = {net.at(3 * i, 3 * k), net.at(3 * i, 3 * k + 1),
                              net.at(3 * i, 3 * k + 2), net.at(3 * i, 3 * k + 3)};
        const double half = t_k + norm(q - p) / 2;
        CHECK(norm(de_boor(knots, c->controls, half) - bezier3(span, 0.5)) <= tolerance);
        t_k += norm(q - p);
      }
    }
  }
  for (std::size_t j = 0; j < 7; ++j) {
    const auto c = input_stringer_bspline(net, j);
    REQUIRE(c);
    CHECK(c->controls.size() == 7);
    CHECK(norm(c->controls.back() - Vec3::load(t.inppn.data() + 3 * (4 * 7 + j))) == 0);
  }
}

TEST_CASE("a curve whose points coincide is a point; equal neighbours are left out") {
  // Curve 1 is a pole (all its points at the origin); on curve 3 two neighbours coincide.
  TestSurface t = test_surface(4, 5, 1, 1);
  for (int j = 0; j < 5; ++j) std::fill_n(t.inppn.data() + 3 * j, 3, 0.0);
  std::copy_n(t.inppn.data() + 3 * (2 * 5 + 1), 3, t.inppn.data() + 3 * (2 * 5 + 2));
  t.surface = interpolate(t.input);
  const BezierNet net = surface_net(t.input, t.surface.patches);
  CHECK_FALSE(input_curve_bspline(net, 0));
  const auto merged = input_curve_bspline(net, 2);
  REQUIRE(merged);
  CHECK(merged->knots.size() == 4);  // three spans of non-zero length
  CHECK(merged->controls.size() == 6);
  for (std::size_t j = 0; j < 5; ++j) CHECK(input_stringer_bspline(net, j));
  // The drawing is still whole: every curve, the pole as a curve of one point repeated.
  const Drawing3 d = surface_curves(t.input, t.surface);
  CHECK(std::count_if(d.items().begin(), d.items().end(),
                      [](const auto& item) { return item.id.role == Role::curve; }) == 7);
}

TEST_CASE("the input points, their border and their tangents come in pen 2") {
  const TestSurface t = golden_surface();
  const Drawing3 d = surface_curves(t.input, t.surface);
  std::size_t borders = 0, tangents = 0, points = 0;
  double longest = 0;
  for (const auto& item : d.items()) {
    if (item.id.role == Role::curve || item.id.role == Role::stringer) continue;
    CHECK(item.style.pen == input_pen);
    switch (item.id.role) {
      case Role::border: {
        ++borders;
        CHECK(item.closed);
        CHECK(d.points(item).size() == 2 * (5 + 4) - 4);
        CHECK(Vec3(d.points(item)[0]) == Vec3::load(t.inppn.data()));
        break;
      }
      case Role::tangent: {
        ++tangents;
        const auto p = d.points(item);
        REQUIRE(p.size() == 2);
        CHECK(Vec3(p[0]) == Vec3::load(t.inppn.data() + 3 * std::size_t(item.id.index - 1)));
        longest = std::max(longest, norm(Vec3(p[1]) - Vec3(p[0])));
        break;
      }
      case Role::point: {
        ++points;
        CHECK(item.kind == Drawing3::Kind::mark);
        CHECK(item.shape == MarkShape::square);
        CHECK(Vec3(d.points(item)[0]) ==
              Vec3::load(t.inppn.data() + 3 * std::size_t(item.id.index - 1)));
        break;
      }
      default:
        FAIL("an item of no expected role");
    }
  }
  CHECK(borders == 1);
  CHECK(tangents == 2 * (5 + 4));  // every border tangent of the test surface is non-zero
  CHECK(points == 5 * 4);
  // The longest tangent is a quarter of the largest extent of the input points (x here).
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t k = 0; k < 20; ++k) {
    lo = std::min(lo, t.inppn.ravel[3 * k]);
    hi = std::max(hi, t.inppn.ravel[3 * k]);
  }
  CHECK(longest == doctest::Approx(0.25 * (hi - lo)).epsilon(1e-12));
}

TEST_CASE("arrays of the wrong shape are refused") {
  TestSurface t = golden_surface();
  Surface bad = t.surface;
  bad.intpn.shape = {3, 3, 3};
  CHECK_THROWS_AS(surface_curves(t.input, bad), DataError);
  bad = t.surface;
  bad.patches = Array({2, 2, 3, 4, 4});
  try {
    surface_net(t.input, bad.patches);
    FAIL("no refusal");
  } catch (const DataError& e) {
    CHECK(e.problem == DataError::Problem::shape);
    CHECK(e.variable == "PATCHES");
  }
}

namespace {

const CadHeader large_header{
    "HULL", "HULL.IGS", {1987, 9, 22, 9, 55, 50}, "A. DESIGNER", "CNUCE PISA"};

// The P section's records: 80 columns, numbered 1, 2, ... in columns 74-80.
void check_p_numbers(const std::string& iges) {
  std::size_t expected = 1, at = 0;
  while (at < iges.size()) {
    const std::size_t end = iges.find('\n', at);
    REQUIRE(end != std::string::npos);
    REQUIRE(end - at == 80);
    if (iges[at + 72] == 'P') {
      REQUIRE(std::stoul(iges.substr(at + 73, 7)) == expected);
      ++expected;
    }
    at = end + 1;
  }
  CHECK(expected > 10000);  // past four carries of the numbers
}

}  // namespace

TEST_CASE("IGES of 551 patches and 49 curves: 80 columns, the P records numbered without a gap") {
  // 30 curves and 20 stringers, one of them a pole (left out).
  TestSurface t = test_surface(30, 20, 0, 0);
  for (int j = 0; j < 20; ++j) std::fill_n(t.inppn.data() + 3 * (5 * 20 + j), 3, 7.0);
  t.surface = interpolate(t.input);
  check_p_numbers(write_iges(t.input, t.surface.patches, large_header, SurfaceForm::patches));
}

}  // namespace igds::test::exchange

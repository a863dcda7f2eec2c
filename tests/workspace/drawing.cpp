// The drawing model (workspace/drawing/): items, shared points, the projection of a drawing in
// space, the flattening of curves and their exact extents.
#include "workspace/drawing/drawing.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "workspace/drawing/flatten.h"
#include "workspace/drawing/project.h"
#include "workspace/kernels/data_error.h"

namespace igds::test {

namespace {

// A point of the rational Bézier span by de Casteljau in homogeneous coordinates.
Point2 rational_point(std::span<const Point2> c, std::span<const double> w, double t) {
  std::vector<std::array<double, 3>> h;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double wk = w.empty() ? 1 : w[k];
    h.push_back({c[k].x * wk, c[k].y * wk, wk});
  }
  for (std::size_t level = 1; level < c.size(); ++level)
    for (std::size_t k = 0; k + level < c.size(); ++k)
      for (int i = 0; i < 3; ++i) h[k][i] = (1 - t) * h[k][i] + t * h[k + 1][i];
  return {h[0][0] / h[0][2], h[0][1] / h[0][2]};
}

Vec3 cubic(const std::array<Vec3, 4>& c, double t) {
  const double s = 1 - t;
  return (s * s * s) * c[0] + (3 * s * s * t) * c[1] + (3 * s * t * t) * c[2] + (t * t * t) * c[3];
}

std::vector<Point2> points_of(const Drawing2& d, const Drawing2::Item& item) {
  std::vector<Point2> out;
  for (Point2 p : d.points(item)) out.push_back(p);
  return out;
}

}  // namespace

TEST_CASE("a drawing keeps its items in order, with their style and identity") {
  Drawing2 d;
  const double line[] = {0, 0, 1, 0, 1, 1};
  d.add_polyline(Point2View(line, 3), {.pen = 2, .dash = Dash::dashed}, {Role::curve, 3}, true);
  d.add_mark({5, 5}, MarkShape::cross, 3, {}, {Role::point, 7});
  d.add_text({1, 2}, "12", 1, {}, {Role::label, 12});
  REQUIRE(d.size() == 3);
  const auto& items = d.items();
  CHECK(items[0].kind == Drawing2::Kind::polyline);
  CHECK(items[0].closed);
  CHECK(items[0].style.pen == 2);
  CHECK(items[0].style.dash == Dash::dashed);
  CHECK(items[0].id == Identity{Role::curve, 3});
  CHECK(points_of(d, items[0]) == std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}});
  CHECK(items[1].shape == MarkShape::cross);
  CHECK(d.points(items[1])[0] == Point2{5, 5});
  CHECK(d.text(items[2]) == "12");
  CHECK(items[2].id.index == 12);
}

TEST_CASE("shared points are read where they are, by rows and by columns") {
  // A 2 x 3 grid of points x y, one plane per curve, held by its owner.
  auto grid = std::make_shared<std::vector<double>>(
      std::vector<double>{0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1});
  Drawing2 d;
  const auto pool = d.share(grid, grid->data(), grid->size());
  d.add_polyline(pool, 6, 3, 2, {}, {Role::curve, 2});     // curve 2: the second row
  d.add_polyline(pool, 2, 2, 6, {}, {Role::stringer, 2});  // stringer 2: a column
  CHECK(points_of(d, d.items()[0]) == std::vector<Point2>{{0, 1}, {1, 1}, {2, 1}});
  CHECK(points_of(d, d.items()[1]) == std::vector<Point2>{{1, 0}, {1, 1}});
  grid.reset();  // the drawing keeps the points alive
  CHECK(points_of(d, d.items()[1]) == std::vector<Point2>{{1, 0}, {1, 1}});
  CHECK_THROWS_AS(d.add_polyline(pool, 2, 3, 6), std::out_of_range);
  CHECK_THROWS_AS(d.add_polyline(9, 0, 1, 2), std::out_of_range);
}

TEST_CASE("curves have degree x spans + 1 controls and one weight per control") {
  Drawing2 d;
  const double four[] = {0, 0, 1, 1, 2, 1, 3, 0};
  d.add_curve(3, Point2View(four, 4));
  CHECK_THROWS_AS(d.add_curve(3, Point2View(four, 3)), std::invalid_argument);
  CHECK_THROWS_AS(d.add_curve(4, Point2View(four, 4)), std::invalid_argument);
  const double w[] = {1, 2};
  CHECK_THROWS_AS(d.add_curve(3, Point2View(four, 4), w), std::invalid_argument);
  CHECK(d.weights(d.items()[0]).empty());
}

TEST_CASE("a projected cubic is exact: each of its points is the projection of the space curve's") {
  const std::array<Vec3, 4> c = {Vec3{0, 0, 0}, Vec3{3, 1, 2}, Vec3{5, -2, 4}, Vec3{8, 0, 1}};
  std::vector<double> flat;
  for (Vec3 p : c) flat.insert(flat.end(), {p.x, p.y, p.z});
  Drawing3 space;
  space.add_curve(3, Vec3View(flat.data(), 4), {}, {.pen = 3}, {Role::curve, 1});
  const Vec3 centre = bounding_box(space).centre();
  for (const View& view :
       {View{Projection::conic, {30, -40, 25}}, View{Projection::assonometric, {110, 130, 120}},
        View{Projection::isometric, {3, 30, 0}}}) {
    const Drawing2 plane = project(space, view, centre);
    REQUIRE(plane.size() == 1);
    const auto& item = plane.items()[0];
    CHECK(item.style.pen == 3);
    CHECK(item.id == Identity{Role::curve, 1});
    CHECK(plane.weights(item).empty() == (view.projection != Projection::conic));
    const auto controls = points_of(plane, item);
    for (double t = 0; t <= 1; t += 0.125) {
      const Vec3 p = cubic(c, t);
      const double in[3] = {p.x, p.y, p.z};
      double expected[2];
      igds::project(view, centre, Vec3View(in, 1), MutablePoint2View(expected, 1));
      const Point2 got = rational_point(controls, plane.weights(item), t);
      CHECK(std::hypot(got.x - expected[0], got.y - expected[1]) < 1e-12);
    }
  }
}

TEST_CASE("a drawing behind the eye is refused") {
  Drawing3 space;
  const double line[] = {0, 0, 0, 0, 10, 0};
  space.add_polyline(Vec3View(line, 2));
  try {
    project(space, {Projection::conic, {0, 5, 0}}, {0, 10, 0});
    FAIL("no refusal");
  } catch (const DataError& e) {
    CHECK(e.problem == DataError::Problem::behind_eye);
  }
}

TEST_CASE("flattening keeps within the tolerance, with as many points as the curve needs") {
  // A quarter of the unit circle as a rational quadratic: weights 1, √2/2, 1.
  const std::vector<Point2> arc = {{1, 0}, {1, 1}, {0, 1}};
  const std::vector<double> w = {1, std::sqrt(0.5), 1};
  for (double tol : {0.1, 0.01, 0.001}) {
    std::vector<Point2> out;
    flatten_span(2, arc, w, tol, out);
    CHECK(out.front() == Point2{1, 0});
    CHECK(out.back() == Point2{0, 1});
    for (Point2 p : out) CHECK(std::abs(std::hypot(p.x, p.y) - 1) < 1e-12);
    // Every chord stays within the tolerance of the circle: its sagitta 1 - cos(θ/2).
    for (std::size_t k = 1; k < out.size(); ++k) {
      const double chord = std::hypot(out[k].x - out[k - 1].x, out[k].y - out[k - 1].y);
      CHECK(1 - std::sqrt(1 - chord * chord / 4) <= tol);
    }
    CAPTURE(out.size());
    CHECK(out.size() < 4 / std::sqrt(tol));
  }
  // A straight cubic needs no intermediate point.
  std::vector<Point2> straight;
  flatten_span(3, std::vector<Point2>{{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {}, 0.5, straight);
  CHECK(straight == std::vector<Point2>{{0, 0}, {3, 0}});
}

TEST_CASE(
    "flattening in space: a rational cubic within the tolerance, the same points as in the plane") {
  // A rational cubic in the plane z = 2: its flattening in space is the plane's, at z = 2.
  const std::vector<Point2> flat = {{0, 0}, {1, 3}, {4, 3}, {5, 0}};
  const std::vector<Vec3> space = {{0, 0, 2}, {1, 3, 2}, {4, 3, 2}, {5, 0, 2}};
  const std::vector<double> w = {1, 3, 0.5, 2};
  for (double tol : {0.1, 0.001}) {
    std::vector<Point2> in_plane;
    std::vector<Vec3> in_space{space[0]};
    flatten_span(3, flat, w, tol, in_plane);
    flatten_span(3, space, w, tol, in_space);
    REQUIRE(in_space.size() == in_plane.size());
    for (std::size_t k = 0; k < in_plane.size(); ++k) {
      CHECK(in_space[k].x == doctest::Approx(in_plane[k].x).epsilon(1e-12));
      CHECK(in_space[k].y == doctest::Approx(in_plane[k].y).epsilon(1e-12));
      CHECK(in_space[k].z == doctest::Approx(2).epsilon(1e-12));
    }
    // Every point is on the curve: the parameter found by bisection on x, y within 1e-9.
    for (Vec3 p : in_space) {
      double lo = 0, hi = 1;
      for (int i = 0; i < 200; ++i) {
        const double mid = (lo + hi) / 2;
        (rational_point(flat, w, mid).x < p.x ? lo : hi) = mid;
      }
      CHECK(std::abs(rational_point(flat, w, lo).y - p.y) < 1e-9);
    }
    CHECK(in_space.size() > (tol < 0.01 ? 20u : 4u));
  }
  // Controls that are not finite: the last control, nothing in between.
  std::vector<Vec3> out;
  flatten_span(3, std::vector<Vec3>{{0, 0, 0}, {INFINITY, 0, 0}, {1, 1, 1}, {2, 0, 0}}, {}, 0.1,
               out);
  CHECK(out == std::vector<Vec3>{{0, 0, 0}, {2, 0, 0}});
}

TEST_CASE("the extremes of a span are where its coordinates turn: the span's own box") {
  // A cubic whose x turns twice inside (controls 0, 3, -2, 1): its box is the curve's, tighter
  // than the controls'.
  const std::vector<Vec3> cubic = {{0, 0, 0}, {3, 1, 0}, {-2, 2, 0}, {1, 3, 0}};
  Vec3 extremes[6];
  const std::size_t n = span_extremes(3, cubic, {}, extremes);
  REQUIRE(n == 2);  // x turns twice, y and z never
  // Sampled densely, the curve's x stays within the extremes' and the ends' x, and reaches them.
  double lo = 0, hi = 1;
  for (std::size_t k = 0; k < n; ++k)
    lo = std::min(lo, extremes[k].x), hi = std::max(hi, extremes[k].x);
  double seen_lo = 1e9, seen_hi = -1e9;
  for (int i = 0; i <= 100000; ++i) {
    const double t = i / 100000.0, s = 1 - t;
    const double x = s * s * s * 0 + 3 * s * s * t * 3 + 3 * s * t * t * -2 + t * t * t * 1;
    seen_lo = std::min(seen_lo, x), seen_hi = std::max(seen_hi, x);
  }
  CHECK(lo == doctest::Approx(seen_lo).epsilon(1e-9));
  CHECK(hi == doctest::Approx(seen_hi).epsilon(1e-9));
  CHECK(hi < 3);
  CHECK(lo > -2);
  // A quarter circle (weights 1, √2/2, 1) from (1, 0) to (0, 1): no coordinate turns inside.
  const std::vector<Vec3> quarter = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<double> w = {1, std::sqrt(0.5), 1};
  CHECK(span_extremes(2, quarter, w, extremes) == 0);
  // An arch (-1, 0), (0, 2), (1, 0) of middle weight 1/2: y turns once, at its middle, at 2/3.
  const std::vector<Vec3> arch = {{-1, 0, 0}, {0, 2, 0}, {1, 0, 0}};
  const std::vector<double> half = {1, 0.5, 1};
  REQUIRE(span_extremes(2, arch, half, extremes) == 1);
  CHECK(extremes[0].x == doctest::Approx(0).scale(1));
  CHECK(extremes[0].y == doctest::Approx(2.0 / 3));
}

}  // namespace igds::test

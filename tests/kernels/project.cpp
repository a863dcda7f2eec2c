// The projections of DISPLAY and SCALE (workspace/kernels/project.h).
#include "workspace/kernels/project.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "tests/kernels/helpers.h"
#include "workspace/kernels/data_error.h"

using namespace igds;
using igds::test::Random;

namespace {

double dist2(Point2 a, Point2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

constexpr double degree = std::numbers::pi / 180;

// The images of the unit axes under ASSON: the columns of its 2 x 3 matrix.
std::vector<Point2> asson_axes(std::array<double, 3> angles) {
  std::vector<Vec3> axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<Point2> out(3);
  asson(axes, angles, out);
  return out;
}

double angle_between(Point2 a, Point2 b) {
  return std::acos((a.x * b.x + a.y * b.y) / (std::hypot(a.x, a.y) * std::hypot(b.x, b.y))) /
         degree;
}

}  // namespace

TEST_CASE("ORTHOG drops a coordinate, planes numbered as DESIM[3]") {
  std::vector<Vec3> in = {{1, 2, 3}, {-4, 5, -6}};
  std::vector<Point2> out(2);
  orthog(in, 1, out);
  CHECK(out == std::vector<Point2>{{1, 2}, {-4, 5}});
  orthog(in, 2, out);
  CHECK(out == std::vector<Point2>{{1, 3}, {-4, -6}});
  orthog(in, 3, out);
  CHECK(out == std::vector<Point2>{{2, 3}, {5, -6}});
  CHECK_THROWS_WITH_AS(orthog(in, 4, out), "INCORRECT PARAMETER", DataError);
  CHECK_THROWS_WITH_AS(orthog(in, 0, out), "INCORRECT PARAMETER", DataError);
}

TEST_CASE("ISOM: a worked example") {
  // Axis 3 (z dropped), 30 degrees: P = (1, 2, 4) gives X = 1 + 4 cos 30 = 1 + 2√3 = 4.4641016,
  // Y = 2 + 4 sin 30 = 4. Axis 1 (x dropped), 45 degrees: P = (2, 3, 5) keeps (y, z) = (3, 5)
  // and adds 2 (cos 45, sin 45) = (√2, √2): (4.4142136, 6.4142136). Axis 2 at 0 degrees: (x + y,
  // z).
  std::vector<Vec3> in = {{1, 2, 4}};
  std::vector<Point2> out(1);
  isom(in, 3, 30, out);
  CHECK(out[0].x == doctest::Approx(4.4641016).epsilon(1e-8));
  CHECK(out[0].y == doctest::Approx(4.0).epsilon(1e-12));
  in = {{2, 3, 5}};
  isom(in, 1, 45, out);
  CHECK(out[0].x == doctest::Approx(4.4142136).epsilon(1e-8));
  CHECK(out[0].y == doctest::Approx(6.4142136).epsilon(1e-8));
  isom(in, 2, 0, out);
  CHECK(dist2(out[0], {5, 5}) < 1e-15);
  isom(in, 2, 90, out);
  CHECK(dist2(out[0], {2, 8}) < 1e-14);
}

TEST_CASE("ISOM refuses an axis other than 1 2 3 and an angle outside 0..90") {
  std::vector<Vec3> in = {{1, 2, 3}};
  std::vector<Point2> out(1);
  CHECK(isom_parameters_valid(1, 0));
  CHECK(isom_parameters_valid(3, 90));
  CHECK_FALSE(isom_parameters_valid(0, 45));
  CHECK_FALSE(isom_parameters_valid(4, 45));
  CHECK_FALSE(isom_parameters_valid(1.5, 45));
  CHECK_FALSE(isom_parameters_valid(2, -1));
  CHECK_FALSE(isom_parameters_valid(2, 90.5));
  CHECK_FALSE(isom_parameters_valid(2, NAN));
  CHECK_THROWS_WITH_AS(isom(in, 4, 30, out), "INCORRECT PARAMETER", DataError);
  CHECK_THROWS_WITH_AS(isom(in, 1, 91, out), "INCORRECT PARAMETER", DataError);
}

TEST_CASE("CONIC maps the centre to the origin and keeps sizes in the plane through the centre") {
  Random rnd(30);
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 centre = rnd.vec(-5, 5);
    const Vec3 view = centre + rnd.vec(-40, 40);
    const Vec3 w = (1 / norm(centre - view)) * (centre - view);
    // Two points in the plane through the centre, perpendicular to the line of sight.
    Vec3 a = cross(w, rnd.vec(-1, 1)), b = cross(w, rnd.vec(-1, 1));
    std::vector<Vec3> in = {centre, centre + 3 * a, centre + 2 * b};
    std::vector<Point2> out(3);
    conic(in, view, centre, out);
    CHECK(dist2(out[0], {0, 0}) < 1e-12);
    CHECK(dist2(out[1], out[2]) == doctest::Approx(norm(3 * a - 2 * b)).epsilon(1e-12));
    CHECK(dist2(out[1], {0, 0}) == doctest::Approx(norm(3 * a)).epsilon(1e-12));
  }
}

TEST_CASE("CONIC keeps z vertical and puts nearer things larger") {
  // Looking along +y from (0, -10, 0): x to the right, z up.
  std::vector<Vec3> in = {{1, 0, 0}, {0, 0, 1}, {1, -5, 0}, {1, 10, 0}};
  std::vector<Point2> out(4);
  conic(in, {0, -10, 0}, {0, 0, 0}, out);
  CHECK(dist2(out[0], {1, 0}) < 1e-15);
  CHECK(dist2(out[1], {0, 1}) < 1e-15);
  CHECK(dist2(out[2], {2, 0}) < 1e-15);
  CHECK(dist2(out[3], {0.5, 0}) < 1e-15);
  // Looking straight down the z axis: a map, x to the right and y up.
  in = {{1, 0, 0}, {0, 2, 0}};
  out.resize(2);
  conic(in, {0, 0, 20}, {0, 0, 0}, out);
  CHECK(dist2(out[0], {1, 0}) < 1e-15);
  CHECK(dist2(out[1], {0, 2}) < 1e-15);
}

TEST_CASE("CONIC refuses a point behind the eye and a view point at the centre") {
  std::vector<Vec3> in = {{0, 0, 0}, {0, -20, 0}};
  std::vector<Point2> out(2, Point2{7, 7});
  CHECK_THROWS_WITH_AS(conic(in, {0, -10, 0}, {0, 0, 0}, out), "INCORRECT PARAMETER", DataError);
  // Nothing was written.
  CHECK(out[0] == Point2{7, 7});
  in = {{0, 0, 0}, {1, -10, 0}};  // beside the eye, in its own plane: still no image
  CHECK_THROWS_WITH_AS(conic(in, {0, -10, 0}, {0, 0, 0}, out), "INCORRECT PARAMETER", DataError);
  CHECK_THROWS_WITH_AS(conic(in, {1, 2, 3}, {1, 2, 3}, out), "INCORRECT PARAMETER", DataError);
}

TEST_CASE("ASSON 120 120 120 foreshortens every axis by sqrt(2/3)") {
  auto axes = asson_axes({120, 120, 120});
  for (auto a : axes) CHECK(std::hypot(a.x, a.y) == doctest::Approx(std::sqrt(2.0 / 3)));
  // z vertical, x to the lower left, y to the lower right.
  CHECK(std::abs(axes[2].x) < 1e-15);
  CHECK(axes[2].y > 0);
  CHECK((axes[0].x < 0 && axes[0].y < 0));
  CHECK((axes[1].x > 0 && axes[1].y < 0));
}

TEST_CASE("ASSON: projected axes meet at the given angles and the matrix rows are orthonormal") {
  Random rnd(31);
  for (int trial = 0; trial < 50; ++trial) {
    // a_xy and a_yz in (90, 180) with a_zx = 360 - a_xy - a_yz also in (90, 180).
    double xy = rnd.uniform(91, 179);
    double yz = rnd.uniform(std::max(91.0, 181 - xy), std::min(179.0, 269 - xy));
    std::array<double, 3> angles = {xy, yz, 360 - xy - yz};
    CAPTURE(angles[0]);
    CAPTURE(angles[1]);
    REQUIRE(asson_parameters_valid(angles));
    auto axes = asson_axes(angles);
    CHECK(angle_between(axes[0], axes[1]) == doctest::Approx(angles[0]).epsilon(1e-9));
    CHECK(angle_between(axes[1], axes[2]) == doctest::Approx(angles[1]).epsilon(1e-9));
    CHECK(angle_between(axes[2], axes[0]) == doctest::Approx(angles[2]).epsilon(1e-9));
    double row1 = 0, row2 = 0, cross_rows = 0;
    for (auto a : axes) row1 += a.x * a.x, row2 += a.y * a.y, cross_rows += a.x * a.y;
    CHECK(row1 == doctest::Approx(1).epsilon(1e-12));
    CHECK(row2 == doctest::Approx(1).epsilon(1e-12));
    CHECK(std::abs(cross_rows) < 1e-12);
  }
}

TEST_CASE("ASSON refuses angles out of range and sums other than 360") {
  CHECK(asson_parameters_valid({110, 130, 120}));
  CHECK_FALSE(asson_parameters_valid({90, 135, 135}));
  CHECK_FALSE(asson_parameters_valid({180, 90, 90}));
  CHECK_FALSE(asson_parameters_valid({80, 140, 140}));
  CHECK_FALSE(asson_parameters_valid({110, 130, 121}));
  CHECK_FALSE(asson_parameters_valid({100, 100, 100}));
  CHECK_FALSE(asson_parameters_valid({NAN, 130, 120}));
  std::vector<Vec3> in = {{1, 2, 3}};
  std::vector<Point2> out(1);
  CHECK_THROWS_WITH_AS(asson(in, {110, 130, 121}, out), "INCORRECT PARAMETER", DataError);
  CHECK_THROWS_WITH_AS(asson(in, {200, 80, 80}, out), "INCORRECT PARAMETER", DataError);
}

TEST_CASE("projections want an output as long as the input") {
  std::vector<Vec3> in(3);
  std::vector<Point2> out(2);
  CHECK_THROWS_AS(orthog(in, 1, out), std::length_error);
  CHECK_THROWS_AS(isom(in, 1, 30, out), std::length_error);
  CHECK_THROWS_AS(conic(in, {0, -1, 0}, {0, 0, 0}, out), std::length_error);
  CHECK_THROWS_AS(asson(in, {120, 120, 120}, out), std::length_error);
}

TEST_CASE("the bounding box: its centre, and whether a point lies inside") {
  std::vector<Vec3> pts = {{0, 0, 0}, {4, -2, 1}, {1, 6, -3}};
  CHECK(bounding_box_centre(pts) == Vec3{2, 2, -1});
  CHECK(bounding_box_centre({}) == Vec3{});
  std::vector<Vec3> huge = {{1.5e308, -1.5e308, 0}, {1.7e308, 1.5e308, 0}};
  CHECK(bounding_box_centre(huge) == Vec3{1.6e308, 0, 0});
  CHECK(inside_bounding_box(pts, {2, 2, -1}));
  CHECK(inside_bounding_box(pts, {4, 6, 1}));
  CHECK_FALSE(inside_bounding_box(pts, {4.01, 2, 0}));
  CHECK_FALSE(inside_bounding_box(pts, {2, 2, -3.5}));
  CHECK_FALSE(inside_bounding_box({}, {0, 0, 0}));
}

TEST_CASE("SCALE: uniform scale, aspect kept, centred, with a margin") {
  // A 2 x 1 image into 1000 x 800 with a 5% margin of the smaller side (40): room 920 x 720, so
  // the width limits the scale to 460 and the image is 920 x 460, centred at (500, 400).
  std::vector<Point2> pts = {{-1, 3}, {1, 4}, {0, 3.5}};
  Scaling s = scale_into(pts, {0, 0, 1000, 800}, 0.05);
  CHECK(s.scale == doctest::Approx(460));
  CHECK(dist2(s.apply({-1, 3}), {40, 170}) < 1e-9);
  CHECK(dist2(s.apply({1, 4}), {960, 630}) < 1e-9);
  // A tall image is limited by the height.
  std::vector<Point2> tall = {{0, 0}, {1, 10}};
  Scaling t = scale_into(tall, {100, 100, 300, 300}, 0);
  CHECK(t.scale == doctest::Approx(20));
  CHECK(dist2(t.apply({0.5, 5}), {200, 200}) < 1e-12);
}

TEST_CASE("SCALE of a single point, a line, nothing and non-finite points") {
  std::vector<Point2> one = {{5, 5}};
  Scaling s = scale_into(one, {0, 0, 100, 50}, 0.1);
  CHECK(dist2(s.apply({5, 5}), {50, 25}) < 1e-12);
  std::vector<Point2> line = {{0, 2}, {10, 2}};
  Scaling l = scale_into(line, {0, 0, 100, 50}, 0.1);
  CHECK(l.scale == doctest::Approx(9));
  CHECK(dist2(l.apply({0, 2}), {5, 25}) < 1e-12);
  Scaling none = scale_into({}, {0, 0, 100, 50}, 0.1);
  CHECK(dist2(none.apply({0, 0}), {50, 25}) < 1e-12);
  std::vector<Point2> mixed = {{0, 0}, {NAN, 1}, {2, INFINITY}, {4, 4}};
  Scaling m = scale_into(mixed, {0, 0, 8, 8}, 0);
  CHECK(m.scale == doctest::Approx(2));
  CHECK(std::isfinite(m.offset_x + m.offset_y));
}

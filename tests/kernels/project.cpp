// The projections of DISPLAY and SCALE (workspace/kernels/project.h).
#include "workspace/kernels/project.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "tests/kernels/helpers.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/processor.h"

using namespace igds;
using igds::test::Flat;
using igds::test::Random;

namespace {

double dist2(Point2 a, Point2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

constexpr double degree = std::numbers::pi / 180;

// The images of the unit axes under ASSON: the columns of its 2 x 3 matrix.
std::vector<Point2> asson_axes(std::array<double, 3> angles) {
  Flat<Vec3> axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Flat<Point2> out(3);
  asson(axes, angles, out);
  return out.points();
}

// The problem a kernel call refuses with.
template <class F>
DataError::Problem problem_of(F f) {
  try {
    f();
  } catch (const DataError& e) {
    return e.problem;
  }
  FAIL("no DataError");
  throw;
}

double angle_between(Point2 a, Point2 b) {
  return std::acos((a.x * b.x + a.y * b.y) / (std::hypot(a.x, a.y) * std::hypot(b.x, b.y))) /
         degree;
}

}  // namespace

TEST_CASE("ORTHOG drops a coordinate, planes numbered as DESIM[3]") {
  Flat<Vec3> in = {{1, 2, 3}, {-4, 5, -6}};
  Flat<Point2> out(2);
  orthog(in, 1, out);
  CHECK(out.points() == std::vector<Point2>{{1, 2}, {-4, 5}});
  orthog(in, 2, out);
  CHECK(out.points() == std::vector<Point2>{{1, 3}, {-4, -6}});
  orthog(in, 3, out);
  CHECK(out.points() == std::vector<Point2>{{2, 3}, {5, -6}});
  CHECK(problem_of([&] { orthog(in, 4, out); }) == DataError::Problem::projection_parameters);
  CHECK(problem_of([&] { orthog(in, 0, out); }) == DataError::Problem::projection_parameters);
}

TEST_CASE("ISOM: a worked example") {
  // Axis 3 (z dropped), 30 degrees: P = (1, 2, 4) gives X = 1 + 4 cos 30 = 1 + 2√3 = 4.4641016,
  // Y = 2 + 4 sin 30 = 4. Axis 1 (x dropped), 45 degrees: P = (2, 3, 5) keeps (y, z) = (3, 5)
  // and adds 2 (cos 45, sin 45) = (√2, √2): (4.4142136, 6.4142136). Axis 2 at 0 degrees: (x + y,
  // z).
  Flat<Vec3> in = {{1, 2, 4}};
  Flat<Point2> out(1);
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
  Flat<Vec3> in = {{1, 2, 3}};
  Flat<Point2> out(1);
  CHECK(isom_parameters_valid(1, 0));
  CHECK(isom_parameters_valid(3, 90));
  CHECK_FALSE(isom_parameters_valid(0, 45));
  CHECK_FALSE(isom_parameters_valid(4, 45));
  CHECK_FALSE(isom_parameters_valid(1.5, 45));
  CHECK_FALSE(isom_parameters_valid(2, -1));
  CHECK_FALSE(isom_parameters_valid(2, 90.5));
  CHECK_FALSE(isom_parameters_valid(2, NAN));
  CHECK(problem_of([&] { isom(in, 4, 30, out); }) == DataError::Problem::projection_parameters);
  CHECK(problem_of([&] { isom(in, 1, 91, out); }) == DataError::Problem::projection_parameters);
}

TEST_CASE("CONIC maps the centre to the origin and keeps sizes in the plane through the centre") {
  Random rnd(30);
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 centre = rnd.vec(-5, 5);
    const Vec3 view = centre + rnd.vec(-40, 40);
    const Vec3 w = (1 / norm(centre - view)) * (centre - view);
    // Two points in the plane through the centre, perpendicular to the line of sight.
    Vec3 a = cross(w, rnd.vec(-1, 1)), b = cross(w, rnd.vec(-1, 1));
    Flat<Vec3> in = {centre, centre + 3 * a, centre + 2 * b};
    Flat<Point2> out(3);
    conic(in, view, centre, out);
    CHECK(dist2(out[0], {0, 0}) < 1e-12);
    CHECK(dist2(out[1], out[2]) == doctest::Approx(norm(3 * a - 2 * b)).epsilon(1e-12));
    CHECK(dist2(out[1], {0, 0}) == doctest::Approx(norm(3 * a)).epsilon(1e-12));
  }
}

TEST_CASE("CONIC keeps z vertical and puts nearer things larger") {
  // Looking along +y from (0, -10, 0): x to the right, z up.
  Flat<Vec3> in = {{1, 0, 0}, {0, 0, 1}, {1, -5, 0}, {1, 10, 0}};
  Flat<Point2> out(4);
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
  Flat<Vec3> in = {{0, 0, 0}, {0, -20, 0}};
  Flat<Point2> out(2, Point2{7, 7});
  CHECK(problem_of([&] {
          conic(in, {0, -10, 0}, {0, 0, 0}, out);
        }) == DataError::Problem::behind_eye);
  // Nothing was written.
  CHECK(out[0] == Point2{7, 7});
  in = {{0, 0, 0}, {1, -10, 0}};  // beside the eye, in its own plane: still no image
  CHECK(problem_of([&] {
          conic(in, {0, -10, 0}, {0, 0, 0}, out);
        }) == DataError::Problem::behind_eye);
  CHECK(problem_of([&] {
          conic(in, {1, 2, 3}, {1, 2, 3}, out);
        }) == DataError::Problem::view_at_centre);
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
  Flat<Vec3> in = {{1, 2, 3}};
  Flat<Point2> out(1);
  CHECK(problem_of([&] {
          asson(in, {110, 130, 121}, out);
        }) == DataError::Problem::projection_parameters);
  CHECK(problem_of([&] {
          asson(in, {200, 80, 80}, out);
        }) == DataError::Problem::projection_parameters);
}

TEST_CASE("projections want an output as long as the input") {
  Flat<Vec3> in(3);
  Flat<Point2> out(2);
  CHECK_THROWS_AS(orthog(in, 1, out), std::length_error);
  CHECK_THROWS_AS(isom(in, 1, 30, out), std::length_error);
  CHECK_THROWS_AS(conic(in, {0, -1, 0}, {0, 0, 0}, out), std::length_error);
  CHECK_THROWS_AS(asson(in, {120, 120, 120}, out), std::length_error);
}

TEST_CASE("the bounding box: its centre, and whether a point lies inside") {
  Flat<Vec3> pts = {{0, 0, 0}, {4, -2, 1}, {1, 6, -3}};
  CHECK(bounding_box_centre(pts) == Vec3{2, 2, -1});
  CHECK(bounding_box_centre(Vec3View{}) == Vec3{});
  Flat<Vec3> huge = {{1.5e308, -1.5e308, 0}, {1.7e308, 1.5e308, 0}};
  CHECK(bounding_box_centre(huge) == Vec3{1.6e308, 0, 0});
  CHECK(inside_bounding_box(pts, {2, 2, -1}));
  CHECK(inside_bounding_box(pts, {4, 6, 1}));
  CHECK_FALSE(inside_bounding_box(pts, {4.01, 2, 0}));
  CHECK_FALSE(inside_bounding_box(pts, {2, 2, -3.5}));
  CHECK_FALSE(inside_bounding_box(Vec3View{}, {0, 0, 0}));
  // Boxes merged axis by axis: one whose points have no y (NaN) adds its x and z alone, and an
  // empty one adds nothing.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Box3 no_y, merged = bounding_box(pts);
  no_y.add(Vec3{-5, nan, 2}), no_y.add(Vec3{7, nan, 2});
  merged.add(no_y), merged.add(Box3{});
  CHECK(merged.lo == Vec3{-5, -2, -3});
  CHECK(merged.hi == Vec3{7, 6, 2});
}

TEST_CASE("the bounding box four points at a time: as one at a time, NaN and strides included") {
  Random rnd(9);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> xyz(3 * 2 * 1003);
  for (double& x : xyz) x = rnd.uniform(-100, 100);
  // A point with no x, a point with nothing, and the largest y among the last three points.
  xyz[3 * 6] = nan;
  xyz[3 * 9] = xyz[3 * 9 + 1] = xyz[3 * 9 + 2] = nan;
  xyz[3 * 1001 + 1] = 500;
  xyz[3 * 2 * 1002 + 2] = -500;  // the least z, the last point of every second one
  for (const KernelCode code : {KernelCode::best, KernelCode::baseline}) {
    use_kernel_code(code);
    for (const std::size_t stride : {3, 6})
      for (const std::size_t n : {0, 1, 3, 4, 7, 1002, 1003}) {
        CAPTURE(code == KernelCode::best);
        CAPTURE(stride);
        CAPTURE(n);
        const Vec3View points(xyz.data(), n, stride);
        Box3 one;
        for (const Vec3 p : points) one.add(p);
        const Box3 box = bounding_box(points);
        CHECK(box.lo == one.lo);
        CHECK(box.hi == one.hi);
        CHECK(box.empty() == (n == 0));
      }
  }
  use_kernel_code(KernelCode::best);
  CHECK(bounding_box(Vec3View(xyz.data(), 1003)).hi.y == 500);
  // Found by a projection as it makes the images, on every core (parts merged).
  std::vector<double> many(3 * (std::size_t(1) << 19));
  for (double& x : many) x = rnd.uniform(-100, 100);
  many[3 * 300000 + 2] = 700;  // in the second part
  const Vec3View points(many.data(), many.size() / 3);
  REQUIRE(threads_for(points.size()) > 1);
  std::vector<double> images(2 * points.size());
  for (const View& v :
       {View{Projection::conic, {900, 800, 700}}, View{Projection::isometric, {3, 30, 0}}}) {
    const Box3 found =
        project_image(v, {}, points, MutablePoint2View(images.data(), points.size()), true).points;
    CHECK(found.lo == bounding_box(points).lo);
    CHECK(found.hi == bounding_box(points).hi);
    CHECK(found.hi.z == 700);
  }
  CHECK(bounding_box(Vec3View(xyz.data(), 1003, 6)).lo.z == -500);
}

TEST_CASE("project() is the four projections, and projection_map() the same as a matrix") {
  Random rnd(32);
  Flat<Vec3> in;
  std::vector<Vec3> list;
  for (int k = 0; k < 20; ++k) list.push_back(rnd.vec(-10, 10));
  in.assign(list);
  const Vec3 centre = bounding_box_centre(in);
  const View views[] = {
      {Projection::conic, {40, -30, 25}},  {Projection::assonometric, {110, 130, 120}},
      {Projection::isometric, {1, 30, 0}}, {Projection::isometric, {2, 45, 0}},
      {Projection::isometric, {3, 90, 0}}, {Projection::orthogonal, {1, 0, 0}},
      {Projection::orthogonal, {2, 0, 0}}, {Projection::orthogonal, {3, 0, 0}},
  };
  for (const View& view : views) {
    CAPTURE(static_cast<int>(view.projection));
    CAPTURE(view.parameters[0]);
    REQUIRE(view_parameters_valid(view));
    Flat<Point2> out(in.size());
    project(view, centre, in, out);
    const ProjectiveMap map = projection_map(view, centre);
    CHECK(map.perspective == (view.projection == Projection::conic));
    if (!map.perspective) {
      // A parallel projection is linear, h = 1: DISPLAY COMBS relies on it.
      CHECK(map.m[0][3] == 0);
      CHECK(map.m[1][3] == 0);
      CHECK((map.m[2][0] == 0 && map.m[2][1] == 0 && map.m[2][2] == 0 && map.m[2][3] == 1));
    }
    for (std::size_t k = 0; k < in.size(); ++k) {
      auto h = map.apply(in[k]);
      CHECK(h[2] > 0);
      CHECK(dist2(out[k], {h[0] / h[2], h[1] / h[2]}) <
            1e-12 * (1 + std::hypot(out[k].x, out[k].y)));
    }
  }
  // The same checks as the functions the entry point dispatches to.
  Flat<Point2> out(in.size());
  CHECK(problem_of([&] {
          project({Projection::orthogonal, {4, 0, 0}}, centre, in, out);
        }) == DataError::Problem::projection_parameters);
  CHECK(problem_of([&] {
          projection_map({Projection::assonometric, {100, 100, 100}}, centre);
        }) == DataError::Problem::projection_parameters);
  CHECK(problem_of([&] {
          project({Projection::conic, {0, 0, 0}}, centre, in, out);
        }) == DataError::Problem::behind_eye);
}

TEST_CASE("an axis or plane beyond an int's range is refused before it is made an integer") {
  const double points[] = {0, 0, 0, 1, 2, 3};
  double out[4];
  for (const Projection projection : {Projection::isometric, Projection::orthogonal}) {
    for (const double code : {-1e308, 1e308, 4294967297.0, 1.5}) {
      CAPTURE(code);
      try {
        project({projection, {code, 30, 0}}, {}, Vec3View(points, 2), MutablePoint2View(out, 2));
        FAIL("projected");
      } catch (const DataError& e) {
        CHECK(e.problem == DataError::Problem::projection_parameters);
      }
    }
  }
}

TEST_CASE(
    "project_image: project() on every core, the first image not finite, the images' box and a "
    "CONIC eye in the points' box found in the same pass") {
  // Enough points to be projected on every core: a sheet 1000 x 800 over z = 0..2.
  const std::size_t columns = 1000, rows = 800, n = columns * rows;
  Flat<Vec3> in(n);
  for (std::size_t k = 0; k < n; ++k)
    in.set(k, {double(k % columns), double(k / columns), std::sin(0.01 * double(k)) + 1});
  const Vec3 centre = bounding_box_centre(in);
  const View views[] = {{Projection::orthogonal, {2, 0, 0}},
                        {Projection::isometric, {3, 30, 0}},
                        {Projection::assonometric, {110, 130, 120}},
                        {Projection::conic, {3000, -2000, 1500}}};
  Flat<Point2> expected(n), out(n);
  for (const View& view : views) {
    CAPTURE(int(view.projection));
    project(view, centre, in, expected);
    const ProjectedImage found = project_image(view, centre, in, out);
    CHECK(found.not_finite == n);
    CHECK(out.d == expected.d);  // bit for bit
    // The box of the images, each side reached by an image.
    CHECK(found.extent == test::box_of_points(expected.d.data(), n));
  }
  // Points near the largest numbers overflow under ISOMETRIC: the first of two, in two parts.
  Flat<Vec3> huge = in;
  for (const std::size_t k : {n - 1000, n / 3 + 7}) huge.set(k, {1.7e308, 1.7e308, 1.7e308});
  CHECK(project_image(views[1], centre, huge, out).not_finite == n / 3 + 7);
  CHECK(project_image(views[0], centre, huge, out).not_finite == n);  // ORTHOGONAL adds nothing

  // A CONIC eye inside the box, points behind it: refused as inside it, not as behind it.
  auto conic = [](Vec3 eye) { return View{Projection::conic, {eye.x, eye.y, eye.z}}; };
  const Vec3 low_corner{100, 100, 0.5};
  CHECK(inside_bounding_box(in, low_corner));
  CHECK(problem_of([&] { project_image(conic(low_corner), centre, in, out); }) ==
        DataError::Problem::view_inside_box);
  CHECK(problem_of([&] { project(conic(low_corner), centre, in, out); }) ==
        DataError::Problem::behind_eye);
  // The eye at the centre: inside the box, said before it has no frame; outside, no frame.
  CHECK(problem_of([&] { project_image(conic(centre), centre, in, out); }) ==
        DataError::Problem::view_inside_box);
  CHECK(problem_of([&] {
          project_image(conic({5000, 0, 0}), {5000, 0, 0}, in, out);
        }) == DataError::Problem::view_at_centre);
  // Outside the box with points behind the eye (towards a centre far beyond the sheet).
  CHECK(problem_of([&] {
          project_image(conic({500, 400, 3}), {500, 400, 1e6}, in, out);
        }) == DataError::Problem::behind_eye);
  CHECK(problem_of([&] {
          project_image({Projection::isometric, {4, 30, 0}}, centre, in, out);
        }) == DataError::Problem::projection_parameters);
}

TEST_CASE("four points at a time: every image and finding as a point at a time makes it") {
  // 1003 points (four at a time, three left over), in front of the CONIC eye, far and near.
  Random rnd(5);
  const std::size_t n = 1003;
  Flat<Vec3> in(n);
  for (std::size_t k = 0; k < n; ++k)
    in.set(k, {rnd.uniform(-50, 50), rnd.uniform(-50, 50), rnd.uniform(-5, 5)});
  const Vec3 eye{300, -200, 150}, centre{};
  const View view{Projection::conic, {eye.x, eye.y, eye.z}};
  auto same_bits = [](const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), 8 * a.size()) == 0;
  };
  const View views[] = {view,
                        {Projection::assonometric, {110, 130, 120}},
                        {Projection::isometric, {1, 30, 0}},
                        {Projection::isometric, {2, 45, 0}},
                        {Projection::isometric, {3, 60, 0}},
                        {Projection::orthogonal, {1, 0, 0}},
                        {Projection::orthogonal, {2, 0, 0}},
                        {Projection::orthogonal, {3, 0, 0}}};
  for (const View& v : views) {
    CAPTURE(int(v.projection));
    CAPTURE(v.parameters[0]);
    Flat<Point2> whole(n), alone(n);
    project(v, centre, in, whole);
    for (std::size_t k = 0; k < n; ++k) {
      Flat<Point2> one(1);
      project(v, centre, Flat<Vec3>{in[k]}, one);
      alone.set(k, one[0]);
    }
    CHECK(same_bits(whole.d, alone.d));
    // The baseline code, and every other point (a stride of two points).
    use_kernel_code(KernelCode::baseline);
    Flat<Point2> baseline(n);
    project(v, centre, in, baseline);
    use_kernel_code(KernelCode::best);
    CHECK(same_bits(whole.d, baseline.d));
    Flat<Point2> strided(n);
    project(v, centre, Vec3View(in.d.data(), (n + 1) / 2, 6),
            MutablePoint2View(strided.d.data(), (n + 1) / 2, 4));
    for (std::size_t k = 0; k < n; k += 2) CHECK(strided[k] == whole[k]);
    // The images' box, the points' box when asked, and the first image not finite: the third of
    // its four.
    Flat<Point2> out(n);
    CHECK(project_image(v, centre, in, out).extent == test::box_of_points(alone.d.data(), n));
    CHECK(project_image(v, centre, in, out).points.empty());
    for (const KernelCode code : {KernelCode::best, KernelCode::baseline}) {
      use_kernel_code(code);
      Box3 one;
      for (std::size_t k = 0; k < n; ++k) one.add(in[k]);
      const Box3 found = project_image(v, centre, in, out, true).points;
      CHECK(found.lo == one.lo);
      CHECK(found.hi == one.hi);
    }
    use_kernel_code(KernelCode::best);
    Flat<Vec3> huge = in;
    huge.set(6, {-1e308, 1e308, -1e308}), huge.set(9, {-1e308, 1e308, -1e308});
    huge.set(6, 1e300 * huge[6]), huge.set(9, 1e300 * huge[9]);  // infinite coordinates
    if (v.projection != Projection::conic)
      CHECK(project_image(v, centre, huge, out).not_finite == 6);
  }

  // What a part finds, against a point at a time: a point behind the eye (the fourth of its
  // four), an image that overflows (the third), and the box about the eye, to which a NaN
  // coordinate adds nothing (every x of the second of four is one).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Flat<Vec3> odd = in;
  odd.resize(12);
  odd.set(7, {400, -300, 200});  // beyond the eye
  odd.set(6, {-1e308, 1e308, -1e308});
  for (const std::size_t k : {1, 5, 9}) odd.set(k, {nan, odd[k].y, odd[k].z});
  Flat<Point2> out(12), one(1);
  auto alone_finds = [&](std::size_t k) {
    return project_part(view, centre, Flat<Vec3>{odd[k]}, one);
  };
  CHECK(alone_finds(7).behind);
  CHECK(alone_finds(6).not_finite == 0);  // in front, its image beyond the largest number
  CHECK_FALSE(alone_finds(6).behind);
  for (const KernelCode code : {KernelCode::best, KernelCode::baseline}) {
    CAPTURE(code == KernelCode::best);
    use_kernel_code(code);
    const ProjectedPart part = project_part(view, centre, odd, out);
    CHECK(part.behind);
    CHECK(part.not_finite == 1);  // the NaN point's image is NaN
    Box3 box;
    for (std::size_t k = 0; k < 12; ++k) box.add(odd[k] - eye);
    CHECK(part.about_eye.lo == box.lo);
    CHECK(part.about_eye.hi == box.hi);
    Flat<Vec3> fewer = odd;
    for (const std::size_t k : {1, 5, 9}) fewer.set(k, in[k]);
    CHECK(project_part(view, centre, fewer, out).not_finite == 6);
    fewer.set(6, in[6]), fewer.set(7, in[7]);
    const ProjectedPart fine = project_part(view, centre, fewer, out);
    CHECK_FALSE(fine.behind);
    CHECK(fine.not_finite == 12);
  }
  use_kernel_code(KernelCode::best);
}

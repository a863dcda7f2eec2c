// The curvature of the interpolated lines (workspace/kernels/curvature.h): a circle, a sphere grid,
// and the patches' own derivatives against differences of an independent evaluation.
#include "workspace/kernels/curvature.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <vector>

#include "tests/kernels/helpers.h"
#include "workspace/kernels/conic_lanes.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"
#include "workspace/kernels/processor.h"
#include "workspace/kernels/project.h"
#include "workspace/kernels/surface.h"

using namespace igds;

namespace {

constexpr double degree = std::numbers::pi / 180;

void set_row(Array& inptg, std::size_t row, Vec3 t, std::size_t point) {
  double* r = inptg.data() + 4 * row;
  t.store(r);
  r[3] = double(point);
}

Vec3 bend(const Array& bends, std::size_t k, std::size_t direction) {
  return Vec3::load(bends.data() + 6 * k + 3 * direction);
}

// Points of a sphere of radius R about `centre`: curve i is the parallel at latitude lat[i],
// stringer j the meridian at longitude lon[j]; the border tangents are the lines' own.
struct Sphere {
  double r;
  Vec3 centre;
  std::vector<double> lat, lon;
  Vec3 at(double phi, double theta) const {
    return centre + r * Vec3{std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta),
                             std::sin(phi)};
  }
  test::Grid grid() const {
    const std::size_t nc = lat.size(), ns = lon.size();
    test::Grid g{int(nc), int(ns), Array({nc * ns, 3}), Array({2 * (nc + ns), 4})};
    auto pts = as_vec3(g.inppn);
    for (std::size_t i = 0; i < nc; ++i)
      for (std::size_t j = 0; j < ns; ++j) pts[i * ns + j] = at(lat[i], lon[j]);
    auto along_curve = [](double theta) { return Vec3{-std::sin(theta), std::cos(theta), 0}; };
    auto along_stringer = [](double phi, double theta) {
      return Vec3{-std::sin(phi) * std::cos(theta), -std::sin(phi) * std::sin(theta),
                  std::cos(phi)};
    };
    for (std::size_t i = 0; i < nc; ++i) {
      set_row(g.inptg, 2 * i, along_curve(lon.front()), i * ns + 1);
      set_row(g.inptg, 2 * i + 1, along_curve(lon.back()), i * ns + ns);
    }
    for (std::size_t j = 0; j < ns; ++j) {
      set_row(g.inptg, 2 * nc + 2 * j, along_stringer(lat.front(), lon[j]), j + 1);
      set_row(g.inptg, 2 * nc + 2 * j + 1, along_stringer(lat.back(), lon[j]),
              (nc - 1) * ns + j + 1);
    }
    return g;
  }
};

std::vector<double> steps(double from, double to, int n) {
  std::vector<double> out;
  for (int k = 0; k <= n; ++k) out.push_back((from + (to - from) * k / n) * degree);
  return out;
}

}  // namespace

TEST_CASE("the curvature vector: its length is the curvature, towards the centre") {
  // A circle of radius 4 at the angle 0, with the speed 3: derivatives (0, 3, 0), (-9/4, 0, 0).
  const Vec3 k = curvature_vector({0, 3, 0}, {-9.0 / 4, 0, 0});
  CHECK(k.x == doctest::Approx(-0.25));
  CHECK(k.y == doctest::Approx(0));
  // A tangential acceleration changes the speed, not the bend.
  const Vec3 same = curvature_vector({0, 3, 0}, {-9.0 / 4, 5, 0});
  CHECK(norm(same - k) < 1e-15);
  CHECK(norm(curvature_vector({0, 0, 0}, {1, 2, 3})) == 0);
  // A derivative that overflowed gives no curvature to draw, not a zero one (DISPLAY COMBS then
  // refuses the comb).
  CHECK(!std::isfinite(norm(curvature_vector({NAN, 1, 0}, {1, 2, 3}))));
  CHECK(!std::isfinite(norm(curvature_vector({1, 1, 0}, {INFINITY, 2, 3}))));
}

TEST_CASE("a circle's comb is constant: 1/R everywhere, towards the centre") {
  // One curve (no patches: the spline of its points) once around a circle of radius 50, and two
  // curves (a cylinder, patches) whose stringers are straight.
  const double r = 50;
  const Vec3 centre{10, -20, 5};
  for (int nocur : {1, 2}) {
    CAPTURE(nocur);
    const int n = 49;  // 48 arcs of 7.5 degrees
    test::Grid g{nocur, n, Array({std::size_t(nocur * n), 3}),
                 Array({std::size_t(2 * (nocur + n)), 4})};
    auto pts = as_vec3(g.inppn);
    for (int i = 0; i < nocur; ++i)
      for (int j = 0; j < n; ++j) {
        const double a = 2 * std::numbers::pi * j / (n - 1);
        pts[i * n + j] = centre + Vec3{r * std::cos(a), r * std::sin(a), 7.0 * i};
      }
    for (int i = 0; i < nocur; ++i) {
      set_row(g.inptg, 2 * i, {0, 1, 0}, i * n + 1);
      set_row(g.inptg, 2 * i + 1, {0, 1, 0}, i * n + n);
    }
    for (int j = 0; j < n; ++j) {
      set_row(g.inptg, 2 * nocur + 2 * j, {0, 0, 1}, j + 1);
      set_row(g.inptg, 2 * nocur + 2 * j + 1, {0, 0, 1}, (nocur - 1) * n + j + 1);
    }
    const SurfaceInput in{nocur, n, 2, 5, &g.inppn, &g.inptg};
    const Surface s = interpolate(in);
    const Array bends = grid_curvature(in, s.patches);
    REQUIRE(bends.shape == std::vector<std::size_t>{s.intpn.shape[0], s.intpn.shape[1], 6});
    const auto grid = as_vec3(s.intpn);
    double least = 1e300, most = 0;
    for (std::size_t k = 0; k < grid.size(); ++k) {
      const Vec3 along = bend(bends, k, 0);
      least = std::min(least, norm(along));
      most = std::max(most, norm(along));
      Vec3 inward = centre - grid[k];
      inward.z = 0;
      CHECK(dot(along, inward) / (norm(along) * norm(inward)) > 0.9999);
      CHECK(norm(bend(bends, k, 1)) < 1e-12);  // straight stringers, or none
    }
    CHECK(least > 0.99 / r);
    CHECK(most < 1.01 / r);
    CHECK((most - least) / most < 0.01);
  }
}

TEST_CASE("a sphere grid: its meridians bend by 1/R, its parallels by 1/(R cos latitude)") {
  // Curves along parallels 10 degrees apart, stringers along meridians. On the input lines the
  // surface is their spline: there the curvature is the sphere's within 1 %. Between them the
  // patches are not a sphere (the twists are zero or Marks's estimate): the combs show that.
  const Sphere sphere{100, {3, 4, -5}, steps(-40, 40, 8), steps(0, 90, 9)};
  const test::Grid g = sphere.grid();
  for (bool marks : {false, true}) {
    CAPTURE(marks);
    const SurfaceInput in{g.nocur, g.nostr, 3, 3, &g.inppn, &g.inptg, marks};
    const Surface s = interpolate(in);
    const Array bends = grid_curvature(in, s.patches);
    const auto grid = as_vec3(s.intpn);
    const std::size_t cols = s.intpn.shape[1];
    double worst_meridian = 0, worst_parallel = 0, worst_inside = 0;
    std::size_t meridian_points = 0, parallel_points = 0;
    for (std::size_t k = 0; k < grid.size(); ++k) {
      const Vec3 p = grid[k] - sphere.centre;
      const double latitude = std::asin(std::clamp(p.z / norm(p), -1.0, 1.0));
      const double parallel = norm(bend(bends, k, 0)) * sphere.r * std::cos(latitude) - 1;
      const double meridian = norm(bend(bends, k, 1)) * sphere.r - 1;
      const bool input_curve = k / cols % 4 == 0, input_stringer = k % cols % 4 == 0;
      if (input_curve) {
        worst_parallel = std::max(worst_parallel, std::abs(parallel));
        ++parallel_points;
      }
      if (input_stringer) {
        worst_meridian = std::max(worst_meridian, std::abs(meridian));
        ++meridian_points;
      }
      if (!input_curve && !input_stringer)
        worst_inside = std::max({worst_inside, std::abs(parallel), std::abs(meridian)});
      // Every comb stands outside: the normal points into the sphere.
      CHECK(dot(bend(bends, k, 1), p) < 0);
    }
    MESSAGE("sphere grid: meridians within " << 100 * worst_meridian << " %, parallels within "
                                             << 100 * worst_parallel << " %, between the input "
                                             << "lines " << 100 * worst_inside << " %");
    CHECK(meridian_points == 10 * 33);
    CHECK(parallel_points == 9 * 37);
    CHECK(worst_meridian < 0.01);
    CHECK(worst_parallel < 0.01);
  }
}

TEST_CASE("the curvature is the patches' own: against differences of an independent evaluation") {
  const test::Grid g = test::wavy_grid(4, 5, 7);
  const SurfaceInput in{g.nocur, g.nostr, 2, 3, &g.inppn, &g.inptg};
  const Surface s = interpolate(in);
  const Array bends = grid_curvature(in, s.patches);
  const GridShape shape = intpn_shape(g.nocur, g.nostr, 2, 3);
  const std::size_t pc = std::size_t(g.nostr) - 1;
  const double h = 1e-4;
  for (std::size_t i = 0; i < shape.rows; ++i)
    for (std::size_t j = 0; j < shape.cols; ++j) {
      // FIT's patch and parameters (docs/kernels.md, "The grid INTPN").
      const std::size_t pi = std::min<std::size_t>(i / 3, g.nocur - 2);
      const std::size_t pj = std::min<std::size_t>(j / 4, g.nostr - 2);
      const double v = double(i - 3 * pi) / 3, u = double(j - 4 * pj) / 4;
      const double* m = s.patches.data() + 48 * (pi * pc + pj);
      auto along = [&](double du, double dv) {
        const Vec3 a = test::eval_patch(m, u - du, v - dv), b = test::eval_patch(m, u, v),
                   c = test::eval_patch(m, u + du, v + dv);
        return curvature_vector((1 / (2 * h)) * (c - a), (1 / (h * h)) * (c - 2.0 * b + a));
      };
      const std::size_t k = i * shape.cols + j;
      const Vec3 curve = along(h, 0), stringer = along(0, h);
      CHECK(norm(bend(bends, k, 0) - curve) < 1e-4 * (1 + norm(curve)));
      CHECK(norm(bend(bends, k, 1) - stringer) < 1e-4 * (1 + norm(stringer)));
    }
}

namespace {

bool same_bits(const double* a, const double* b) {
  return std::memcmp(a, b, 3 * sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("four points at a time and one at a time, vector and baseline code: the same bits") {
  const test::Grid g = test::wavy_grid(5, 6, 11);
  // 3 and 6 points a patch: u = 1/3 is one point at a time in the first (fewer than four in a
  // patch), the third of the first four in the second. The last patch has one point more.
  const SurfaceInput third{g.nocur, g.nostr, 2, 2, &g.inppn, &g.inptg};
  const SurfaceInput sixth{g.nocur, g.nostr, 2, 5, &g.inppn, &g.inptg};
  const Array patches = interpolate(third).patches;
  const Array by3 = grid_curvature(third, patches), by6 = grid_curvature(sixth, patches);
  const std::size_t cols3 = intpn_shape(g.nocur, g.nostr, 2, 2).cols;
  const std::size_t cols6 = intpn_shape(g.nocur, g.nostr, 2, 5).cols;
  const std::size_t rows = intpn_shape(g.nocur, g.nostr, 2, 2).rows;
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols3; ++j)
      for (std::size_t d = 0; d < 6; d += 3) {
        CAPTURE(i);
        CAPTURE(j);
        CHECK(same_bits(by3.data() + 6 * (i * cols3 + j) + d,
                        by6.data() + 6 * (i * cols6 + 2 * j) + d));
      }
  // A grid whose points coincide has no direction anywhere: every curvature vector is zero.
  test::Grid still = g;
  std::fill(still.inppn.data(), still.inppn.data() + still.inppn.size(), 1.0);
  const SurfaceInput flat{g.nocur, g.nostr, 2, 5, &still.inppn, &still.inptg};
  for (const KernelCode code : {KernelCode::best, KernelCode::baseline}) {
    CAPTURE(code == KernelCode::best);
    use_kernel_code(code);
    const Array again = grid_curvature(sixth, patches);
    CHECK(std::memcmp(again.data(), by6.data(), by6.size() * sizeof(double)) == 0);
    const Array none = grid_curvature(flat, interpolate(flat).patches);
    CHECK(std::all_of(none.data(), none.data() + none.size(), [](double x) { return x == 0; }));
  }
  use_kernel_code(KernelCode::best);
}

TEST_CASE(
    "four patches at a time, four points of a patch at a time, one at a time: the same bits") {
  // Every patch of a row the same matrix: a point at u is then the same in each patch of the row,
  // whichever way it is made. With 6 points a patch (7 in the last) and 10 patches a row, the
  // first eight go four patches at a time, the ninth a patch at a time, and the last's u = 2/3
  // (its fifth point) one at a time.
  const test::Grid g = test::wavy_grid(5, 11, 3);
  const SurfaceInput in{g.nocur, g.nostr, 2, 5, &g.inppn, &g.inptg};
  Array same = interpolate(in).patches;
  const std::size_t per_row = std::size_t(g.nostr) - 1;
  for (std::size_t i = 0; i + 1 < std::size_t(g.nocur); ++i)
    for (std::size_t j = 1; j < per_row; ++j)
      std::copy_n(same.data() + 48 * per_row * i, 48, same.data() + 48 * (per_row * i + j));
  const GridShape shape = intpn_shape(g.nocur, g.nostr, 2, 5);
  for (const KernelCode code : {KernelCode::best, KernelCode::baseline}) {
    CAPTURE(code == KernelCode::best);
    use_kernel_code(code);
    const Array bends = grid_curvature(in, same);
    for (std::size_t i = 0; i < shape.rows; ++i)
      for (std::size_t m = 0; m < 6; ++m)
        for (std::size_t j = 0; j + 1 < per_row; ++j) {
          CAPTURE(i);
          CAPTURE(m);
          CAPTURE(j);
          const std::size_t last = i * shape.cols + 6 * (per_row - 1) + m;
          const std::size_t here = i * shape.cols + 6 * j + m;
          CHECK(same_bits(bends.data() + 6 * here, bends.data() + 6 * last));
          CHECK(same_bits(bends.data() + 6 * here + 3, bends.data() + 6 * last + 3));
        }
  }
  use_kernel_code(KernelCode::best);
}

TEST_CASE("patches of another shape are refused, not read") {
  const test::Grid g = test::wavy_grid(3, 3, 1);
  const SurfaceInput in{g.nocur, g.nostr, 1, 1, &g.inppn, &g.inptg};
  const Array wrong({2, 1, 3, 4, 4});
  CHECK_THROWS_AS(grid_curvature(in, wrong), DataError);
}

TEST_CASE("the combs' vectors four points at a time: as one at a time, overflow and NaN included") {
  const test::Grid g = test::wavy_grid(5, 6, 11);
  const SurfaceInput in{g.nocur, g.nostr, 2, 5, &g.inppn, &g.inptg};
  const GridShape shape = intpn_shape(g.nocur, g.nostr, 2, 5);
  const std::size_t n = shape.rows * shape.cols;
  const Array patches = interpolate(in).patches;
  // Patches scaled by 1e-154 bend 1e154 times as much: the squares of the largest overflow.
  // A number that is not finite in one patch makes vectors that are not.
  Array tiny = patches, holed = patches;
  for (double& x : tiny.ravel) x *= 1e-154;
  holed.ravel[48 * 2 + 17] = std::numeric_limits<double>::quiet_NaN();
  const ProjectiveMap map = projection_map({Projection::assonometric, {110, 130, 120}}, {});
  auto same = [](double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
  };
  for (const Array* p :
       {&patches, static_cast<const Array*>(&tiny), static_cast<const Array*>(&holed)})
    for (const KernelCode code : {KernelCode::best, KernelCode::baseline}) {
      CAPTURE(p == &patches ? "patches" : p == &tiny ? "tiny" : "holed");
      CAPTURE(code == KernelCode::best);
      use_kernel_code(code);
      const Array bends = grid_curvature(in, *p);
      std::vector<double> one_images(4 * n), images(4 * n);
      CurvatureRows rows(in, *p), measure(in, *p);
      LargestCurvature all;
      // Row by row: the largest of each row must be found where it is.
      for (std::size_t i = 0; i < shape.rows; ++i) {
        CAPTURE(i);
        LargestCurvature one, lanes, measured;
        for (std::size_t k = i * shape.cols; k < (i + 1) * shape.cols; ++k)
          comb_vectors(bend(bends, k, 0), bend(bends, k, 1), &map, one_images.data() + 4 * k, one);
        rows.combs(i, i + 1, lanes, &map, images.data() + 4 * shape.cols * i);
        measure.combs(i, i + 1, measured);
        CHECK(same(lanes.squared, one.squared));
        CHECK(same(lanes.overflowing, one.overflowing));
        CHECK(same(measured.squared, one.squared));
        CHECK(same(measured.overflowing, one.overflowing));
        all.add(one);
      }
      CHECK(std::equal(images.begin(), images.end(), one_images.begin(), same));
      if (p == &tiny) CHECK(all.overflowing > 1e150);
      if (p == &holed)
        CHECK(std::any_of(images.begin(), images.end(), [](double x) { return std::isnan(x); }));
    }
  use_kernel_code(KernelCode::best);
}

TEST_CASE("the largest curvature: squares compared, lengths where they overflow, NaN none") {
  LargestCurvature largest;
  largest.add(Vec3{3, 4, 0});
  CHECK(largest.squared == 25);
  largest.add(Vec3{1, 0, 0});
  CHECK(largest.squared == 25);
  largest.add(Vec3{1e200, 0, 0});  // its square overflows: its length is kept
  largest.add(Vec3{0, 1e180, 0});  // and the larger of such lengths
  largest.add(Vec3{std::numeric_limits<double>::quiet_NaN(), 0, 0});
  largest.add(Vec3{std::numeric_limits<double>::infinity(), 0, 0});
  CHECK(largest.squared == 25);
  CHECK(largest.overflowing == 1e200);
  CHECK(largest.length() == 1e200);
  LargestCurvature other;
  other.add(Vec3{0, 0, 6});
  other.add(largest);
  CHECK(other.squared == 36);
  CHECK(other.length() == 1e200);
}

TEST_CASE(
    "the combs seen from an eye as they are made: as their ends projected one at a time, "
    "measured") {
  // 10 patches a row, 6 points a patch (7 in the last): four patches at a time, a patch at a
  // time and one point at a time. One point far out, whose combs' images overflow, and one that is
  // not a number (behind the eye, and not finite), each in turn where each way makes it.
  const test::Grid g = test::wavy_grid(5, 11, 3);
  const SurfaceInput in{g.nocur, g.nostr, 2, 5, &g.inppn, &g.inptg};
  const Surface s = interpolate(in);
  const GridShape shape = intpn_shape(g.nocur, g.nostr, 2, 5);
  const std::size_t n = shape.rows * shape.cols;
  const Vec3 centre = bounding_box_centre(as_vec3(g.inppn)), eye{-40, -30, 25};
  const View view{Projection::conic, {eye.x, eye.y, eye.z}};
  const ConicFrame frame = conic_frame(eye, centre);
  const Array bends = grid_curvature(in, s.patches);
  const double scale = 0.5;
  auto same = [](double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
  };
  const std::size_t row = 2 * shape.cols;
  for (const std::size_t odd : {std::size_t(0), row + 1, row + 6 * 8 + 2, row + 6 * 9 + 5})
    for (const double value : {1e308, std::numeric_limits<double>::quiet_NaN(), 3.0})
      for (const KernelCode code : {KernelCode::best, KernelCode::baseline}) {
        CAPTURE(odd);
        CAPTURE(value);
        CAPTURE(code == KernelCode::best);
        use_kernel_code(code);
        Array points = s.intpn;
        points.ravel[3 * odd] = value;
        // The ends in space one at a time, then projected as any points are.
        std::vector<double> ends(6 * n), expected(4 * n), images(4 * n);
        for (std::size_t k = 0; k < n; ++k)
          comb_ends(Vec3::load(points.data() + 3 * k), bend(bends, k, 0), bend(bends, k, 1), scale,
                    ends.data() + 6 * k);
        const ProjectedPart want = project_part(view, centre, Vec3View(ends.data(), 2 * n),
                                                MutablePoint2View(expected.data(), 2 * n));
        LargestCurvature measured, largest;
        for (std::size_t k = 0; k < n; ++k)
          largest.add(bend(bends, k, 0)), largest.add(bend(bends, k, 1));
        const ProjectedPart got = CurvatureRows(in, s.patches)
                                      .conic_combs(0, shape.rows, points.data(), scale, frame, eye,
                                                   images.data(), measured);
        CHECK(std::equal(images.begin(), images.end(), expected.begin(), same));
        CHECK(measured.squared == largest.squared);
        CHECK(measured.overflowing == largest.overflowing);
        CHECK(got.not_finite == want.not_finite);
        CHECK(got.behind == want.behind);
        CHECK(got.about_eye.lo == want.about_eye.lo);
        CHECK(got.about_eye.hi == want.about_eye.hi);
        if (value != 3.0) CHECK(got.not_finite == 2 * odd);
        CHECK(got.behind == std::isnan(value));
      }
  use_kernel_code(KernelCode::best);
}

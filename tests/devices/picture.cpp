// The generic layer (devices/picture.h): what an image draws, one scale, clipping, rounding.
#include "devices/picture.h"

#include <doctest/doctest.h>

#include "tests/devices/support.h"

namespace igds::test::devices {

namespace {

Point2 point(const Image& im, std::size_t c, std::size_t r) {
  std::size_t rows = im.points.shape[1];
  return {im.points.ravel[2 * (c * rows + r)], im.points.ravel[2 * (c * rows + r) + 1]};
}

}  // namespace

TEST_CASE("picture_of SURFACE: one polyline per curve, then one per stringer") {
  Image im = surface_image(4, 6);
  Picture pic = picture_of(im);
  REQUIRE(pic.paths.size() == 4 + 6);
  CHECK(pic.marks.empty());
  for (std::size_t c = 0; c < 4; ++c) {
    REQUIRE(pic.paths[c].size() == 6);
    for (std::size_t r = 0; r < 6; ++r) CHECK(pic.paths[c][r] == point(im, c, r));
  }
  for (std::size_t r = 0; r < 6; ++r) {
    REQUIRE(pic.paths[4 + r].size() == 4);
    for (std::size_t c = 0; c < 4; ++c) CHECK(pic.paths[4 + r][c] == point(im, c, r));
  }
  CHECK(pic.description == std::vector<std::string>{"SURFACE", "ASSONOMETRIC", "110 130 120"});
}

TEST_CASE("picture_of INPUT: the border once around, arrows, a mark per point") {
  Image im = input_image(3, 4);
  Picture pic = picture_of(im);
  CHECK(pic.marks.size() == 12);
  REQUIRE(pic.paths.size() == 1 + 3);
  const auto& ring = pic.paths[0];
  // 4 + 2 + 3 + 1 points around a 3 x 4 grid, then back to the first.
  REQUIRE(ring.size() == 11);
  CHECK(ring.front() == ring.back());
  CHECK(ring[3] == point(im, 0, 3));
  CHECK(ring[5] == point(im, 2, 3));
  CHECK(ring[8] == point(im, 2, 0));
  CHECK(ring[9] == point(im, 1, 0));
  // An interior point (1, 1) is not on the border.
  for (auto p : ring) CHECK(!(p == point(im, 1, 1)));
  // Arrows: base, tip, two barbs, tip; lengths proportional to the tangents; the longest is a
  // quarter of the image's larger side.
  Box b = bounds(Picture{{ring}, {}, {}});
  double extent = std::max(b.x1 - b.x0, b.y1 - b.y0);
  double lengths[3];
  const double tangent[3] = {std::hypot(3, 1), 4, std::hypot(1, 0.5)};
  for (int i = 0; i < 3; ++i) {
    const auto& a = pic.paths[1 + i];
    REQUIRE(a.size() == 5);
    CHECK(a[1] == a[4]);
    lengths[i] = std::hypot(a[1].x - a[0].x, a[1].y - a[0].y);
    CHECK(std::hypot(a[2].x - a[1].x, a[2].y - a[1].y) == doctest::Approx(lengths[i] / 4));
  }
  CHECK(lengths[1] == doctest::Approx(arrow_fraction * extent));
  CHECK(lengths[0] / lengths[1] == doctest::Approx(tangent[0] / tangent[1]));
  CHECK(lengths[2] / lengths[1] == doctest::Approx(tangent[2] / tangent[1]));
  // The tip lies along the tangent.
  const auto& a0 = pic.paths[1];
  CHECK((a0[1].x - a0[0].x) / (a0[1].y - a0[0].y) == doctest::Approx(3.0));
  CHECK(pic.description == std::vector<std::string>{"INPUT", "CONIC", "12.5 -40 1000"});
}

TEST_CASE("picture_of: zero tangents draw no arrow; bad shapes draw nothing") {
  Image im = input_image(2, 2);
  im.arrows.ravel = {0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 0};
  CHECK(picture_of(im).paths.size() == 1);
  im.arrows = Array({2, 3});
  CHECK(picture_of(im).paths.size() == 1);
  Image bad;
  bad.points = Array({2, 2, 3});
  CHECK(picture_of(bad).paths.empty());
  bad.points.shape = {2, 2, 2};  // ravel of the wrong size
  CHECK(picture_of(bad).paths.empty());
}

TEST_CASE("picture_of: a non-finite point breaks its lines") {
  Image im = surface_image(3, 5);
  im.points.ravel[2 * (1 * 5 + 2)] = std::numeric_limits<double>::infinity();
  Picture pic = picture_of(im);
  // Curve 2 becomes two pieces of 2 points; stringer 3 loses its middle point: two lone points.
  CHECK(pic.paths.size() == 3 + 1 + 5 - 1);
  for (const auto& p : pic.paths)
    for (auto q : p) CHECK(std::isfinite(q.x));
}

TEST_CASE("describe: the projections and their parameters, at most `width` characters") {
  CHECK(describe({1, Projection::orthogonal, {2, 0, 0}}, 17) ==
        std::vector<std::string>{"SURFACE", "ORTHOGONAL", "XZ"});
  CHECK(describe({0, Projection::isometric, {3, 30, 0}}, 17) ==
        std::vector<std::string>{"INPUT", "ISOMETRIC", "AXIS Z ANGLE 30"});
  CHECK(describe({1, Projection::conic, {-1.5, 1234567.25, 1e-9}}, 17) ==
        std::vector<std::string>{"SURFACE", "CONIC", "-1.5", "1234567.25", "1E-9"});
  for (const auto& line : describe({1, Projection::conic, {-1.234567891e-17, 1, 2}}, 8))
    CHECK(line.size() <= 8);
  CHECK(plain_number(-3.25) == "-3.25");
  CHECK(plain_number(110) == "110");
}

TEST_CASE("fit: one scale, aspect kept, centred, room for the marks") {
  Picture pic{{{{0, 0}, {10, 5}}}, {{0, 0}}, {}};
  Placement at = fit(pic, {0, 0, 100, 100}, 5);
  CHECK(fit(Picture{pic.paths, {}, {}}, {0, 0, 100, 100}, 5).scale == doctest::Approx(10));
  CHECK(at.scale == doctest::Approx(9));
  Point2 a = at.apply({0, 0}), b = at.apply({10, 5});
  CHECK(a.x == doctest::Approx(5));
  CHECK(b.x == doctest::Approx(95));
  CHECK((a.y + b.y) / 2 == doctest::Approx(50));
  // A single point goes to the centre.
  Placement one = fit(Picture{{}, {{3, 4}}, {}}, {0, 0, 100, 50}, 2);
  CHECK(one.apply({3, 4}).x == doctest::Approx(50));
  CHECK(one.apply({3, 4}).y == doctest::Approx(25));
  // A vertical line uses the height.
  Placement v = fit(Picture{{{{1, 0}, {1, 10}}}, {}, {}}, {0, 0, 100, 50}, 0);
  CHECK(v.scale == doctest::Approx(5));
}

TEST_CASE("clip_segment: Liang-Barsky in floating point") {
  Box box{0, 0, 10, 10};
  Point2 a{-5, 5}, b{15, 5};
  REQUIRE(clip_segment(a, b, box));
  CHECK(a == Point2{0, 5});
  CHECK(b == Point2{10, 5});
  a = {-5, -5}, b = {-1, 20};
  CHECK(!clip_segment(a, b, box));
  a = {2, 2}, b = {8, 3};
  REQUIRE(clip_segment(a, b, box));
  CHECK(a == Point2{2, 2});
  CHECK(b == Point2{8, 3});
  a = {5, -10}, b = {5, 30};
  REQUIRE(clip_segment(a, b, box));
  CHECK(a == Point2{5, 0});
  CHECK(b == Point2{5, 10});
}

TEST_CASE("place: clipped before rounding, rounded to the nearest unit, split where it leaves") {
  Picture pic{{{{-10, 2.4}, {5.5, 2.6}, {30, 2.6}, {30, 8}, {5, 8.49}}}, {}, {}};
  Placed placed = place(pic, {}, 0, {0, 0, 20, 20});
  CHECK(placed.clipped);
  REQUIRE(placed.paths.size() == 2);
  // (-10, 2.4)-(5.5, 2.6) enters at x = 0, y = 2.4 + 0.2 * 10 / 15.5.
  CHECK(placed.paths[0] == DevicePath{{0, 3}, {6, 3}, {20, 3}});
  CHECK(placed.paths[1] == DevicePath{{20, 8}, {5, 8}});
  // Rounding, never truncation; points that round to the same unit count once.
  Placed inside =
      place(Picture{{{{1.5, 1.5}, {2.49, 1.5}, {2.5, 1.49}}, {{4, 4}, {4.4, 3.6}}}, {}, {}}, {}, 0,
            {0, 0, 20, 20});
  CHECK(!inside.clipped);
  REQUIRE(inside.paths.size() == 1);
  CHECK(inside.paths[0] == DevicePath{{2, 2}, {3, 1}});
}

TEST_CASE("place: marks are squares of the given half side, never out of the clip box") {
  Picture pic{{}, {{0, 0}, {10, 10}}, {}};
  Placed placed = place(pic, {}, 2, {0, 0, 100, 100});
  CHECK(placed.clipped);  // the mark at the origin sticks out
  REQUIRE(placed.paths.size() == 2);
  CHECK(placed.paths[1] == DevicePath{{8, 8}, {12, 8}, {12, 12}, {8, 12}, {8, 8}});
  for (auto p : placed.paths[0]) CHECK((p.x >= 0 && p.y >= 0));
}

}  // namespace igds::test::devices

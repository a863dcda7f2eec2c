// What an IGDS image becomes in a drawing (commands/picture.h).
#include "commands/picture.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tests/devices/support.h"

namespace igds::test::devices {

namespace {

// The lines and marks of a picture as the devices see them: polylines split wherever a point is
// not finite, pieces of fewer than two points dropped.
struct Shapes {
  std::vector<std::vector<Point2>> paths;
  std::vector<Point2> marks;
};
Shapes shapes(const Picture& pic) {
  Shapes out;
  for (const auto& item : pic.drawing.items()) {
    const auto points = pic.drawing.points(item);
    if (item.kind == Drawing2::Kind::mark) {
      out.marks.push_back(points[0]);
      continue;
    }
    std::vector<Point2> piece;
    for (Point2 p : points) {
      if (std::isfinite(p.x) && std::isfinite(p.y)) {
        piece.push_back(p);
        continue;
      }
      if (piece.size() >= 2) out.paths.push_back(piece);
      piece.clear();
    }
    if (piece.size() >= 2) out.paths.push_back(piece);
  }
  return out;
}

Point2 point(const Image& im, std::size_t c, std::size_t r) {
  std::size_t rows = im.points.shape[1];
  return {im.points.ravel[2 * (c * rows + r)], im.points.ravel[2 * (c * rows + r) + 1]};
}

}  // namespace

TEST_CASE("picture_of SURFACE: one polyline per curve, then one per stringer") {
  Image im = surface_image(4, 6);
  Picture picture = picture_of(im);
  Shapes pic = shapes(picture);
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
  CHECK(picture.caption == std::vector<std::string>{"SURFACE", "ASSONOMETRIC", "110 130 120"});
  // Curves and stringers say which they are.
  CHECK(picture.drawing.items()[2].id == Identity{Role::curve, 3});
  CHECK(picture.drawing.items()[4 + 5].id == Identity{Role::stringer, 6});
}

TEST_CASE("picture_of INPUT: the border once around, arrows, a mark per point") {
  Image im = input_image(3, 4);
  Picture picture = picture_of(im);
  Shapes pic = shapes(picture);
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
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (Point2 p : ring)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  double extent = std::max(x1 - x0, y1 - y0);
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
  CHECK(picture.caption == std::vector<std::string>{"INPUT", "CONIC", "12.5 -40 1000"});
  // Marks name their point, row by row; the point numbers come after them.
  const auto& items = picture.drawing.items();
  const auto last_mark = std::find_if(items.rbegin(), items.rend(), [](const auto& item) {
    return item.kind == Drawing2::Kind::mark;
  });
  REQUIRE(last_mark != items.rend());
  CHECK(last_mark->id == Identity{Role::point, 12});
  CHECK(std::all_of(items.rbegin(), last_mark,
                    [](const auto& item) { return item.kind == Drawing2::Kind::text; }));
  CHECK(items[0].id.role == Role::border);
}

TEST_CASE("picture_of: zero tangents draw no arrow; bad shapes draw nothing") {
  Image im = input_image(2, 2);
  im.arrows.ravel = {0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 0};
  CHECK(shapes(picture_of(im)).paths.size() == 1);
  im.arrows = Array({2, 3});
  CHECK(shapes(picture_of(im)).paths.size() == 1);
  Image bad;
  bad.points = Array({2, 2, 3});
  CHECK(shapes(picture_of(bad)).paths.empty());
  bad.points.shape = {2, 2, 2};  // ravel of the wrong size
  CHECK(shapes(picture_of(bad)).paths.empty());
}

TEST_CASE("picture_of: a non-finite point breaks its lines") {
  Image im = surface_image(3, 5);
  im.points.ravel[2 * (1 * 5 + 2)] = std::numeric_limits<double>::infinity();
  Shapes pic = shapes(picture_of(im));
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

}  // namespace igds::test::devices

// The generic layer (devices/render.h): one scale, curves flattened and marks stroked in device
// units, clipping before rounding.
#include "devices/render.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <memory>

#include "tests/devices/support.h"

namespace igds::test::devices {

namespace {

// A drawing of polylines (and marks at the given points).
Drawing2 drawing(std::initializer_list<std::vector<Point2>> lines, std::vector<Point2> marks = {},
                 double mark = 3) {
  Drawing2 d;
  for (const auto& line : lines) {
    std::vector<double> xy;
    for (Point2 p : line) xy.insert(xy.end(), {p.x, p.y});
    d.add_polyline(Point2View(xy.data(), line.size()));
  }
  for (Point2 m : marks) d.add_mark(m, MarkShape::square, mark);
  return d;
}

DevicePath path(const Placed& placed, std::size_t k) {
  return {placed.paths[k].begin(), placed.paths[k].end()};
}

// The points of a grid of `planes` curves of `rows` points, as a surface image holds them: point
// r of curve c at xy(c, r).
template <class XY>
std::shared_ptr<std::vector<double>> grid_points(std::size_t planes, std::size_t rows,
                                                 const XY& xy) {
  auto grid = std::make_shared<std::vector<double>>(2 * planes * rows);
  for (std::size_t c = 0; c < planes; ++c)
    for (std::size_t r = 0; r < rows; ++r) {
      const Point2 p = xy(static_cast<double>(c), static_cast<double>(r));
      (*grid)[2 * (c * rows + r)] = p.x;
      (*grid)[2 * (c * rows + r) + 1] = p.y;
    }
  return grid;
}

// The box of every point of the placed paths, read one by one.
DeviceBox box_of_paths(const Placed& placed) {
  DeviceBox b;
  for (std::size_t k = 0; k < placed.paths.size(); ++k)
    for (const DevicePoint p : placed.paths[k]) {
      b.x0 = std::min(b.x0, p.x), b.x1 = std::max(b.x1, p.x);
      b.y0 = std::min(b.y0, p.y), b.y1 = std::max(b.y1, p.y);
    }
  return b;
}

// A drawing of `grid` shared as a surface image is: its curves one after another, then its
// stringers a row apart.
Drawing2 shared_grid(const std::shared_ptr<std::vector<double>>& grid, std::size_t planes,
                     std::size_t rows) {
  Drawing2 d;
  const auto pool = d.share(grid, grid->data(), grid->size());
  for (std::size_t c = 0; c < planes; ++c)
    d.add_polyline(pool, 2 * c * rows, rows, 2, {}, {Role::curve, int(c + 1)});
  for (std::size_t r = 0; r < rows; ++r)
    d.add_polyline(pool, 2 * r, planes, 2 * rows, {}, {Role::stringer, int(r + 1)});
  return d;
}

std::vector<DevicePath> paths(const Placed& placed) {
  std::vector<DevicePath> out;
  for (std::size_t k = 0; k < placed.paths.size(); ++k)
    out.emplace_back(placed.paths[k].begin(), placed.paths[k].end());
  return out;
}

}  // namespace

TEST_CASE("fit: one scale, aspect kept, centred, room for the marks") {
  Drawing2 d = drawing({{{0, 0}, {10, 5}}}, {{0, 0}});
  Placement at = fit(d, {0, 0, 100, 100}, 5);
  CHECK(fit(drawing({{{0, 0}, {10, 5}}}), {0, 0, 100, 100}, 5).scale == doctest::Approx(10));
  CHECK(at.scale == doctest::Approx(9));
  Point2 a = at.apply({0, 0}), b = at.apply({10, 5});
  CHECK(a.x == doctest::Approx(5));
  CHECK(b.x == doctest::Approx(95));
  CHECK((a.y + b.y) / 2 == doctest::Approx(50));
  // A single point goes to the centre.
  Placement one = fit(drawing({}, {{3, 4}}), {0, 0, 100, 50}, 2);
  CHECK(one.apply({3, 4}).x == doctest::Approx(50));
  CHECK(one.apply({3, 4}).y == doctest::Approx(25));
  // A vertical line uses the height.
  Placement v = fit(drawing({{{1, 0}, {1, 10}}}), {0, 0, 100, 50}, 0);
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
  Drawing2 d = drawing({{{-10, 2.4}, {5.5, 2.6}, {30, 2.6}, {30, 8}, {5, 8.49}}});
  Placed placed = place(d, {}, {0, 0, 20, 20}, {});
  CHECK(placed.clipped);
  // (-10, 2.4)-(5.5, 2.6) enters at x = 0, y = 2.4 + 0.2 * 10 / 15.5.
  CHECK(paths(placed) == std::vector<DevicePath>{{{0, 3}, {6, 3}, {20, 3}}, {{20, 8}, {5, 8}}});
  // Rounding, never truncation; points that round to the same unit count once.
  Placed inside = place(drawing({{{1.5, 1.5}, {2.49, 1.5}, {2.5, 1.49}}, {{4, 4}, {4.4, 3.6}}}), {},
                        {0, 0, 20, 20}, {});
  CHECK(!inside.clipped);
  CHECK(paths(inside) == std::vector<DevicePath>{{{2, 2}, {3, 1}}});
  // Halves up below zero too: floor(v + 0.5).
  Placed below = place(drawing({{{-1.5, -2.5}, {-0.5, 0.5}, {-2.51, -0.49}, {-7.5, -7.49}}}), {},
                       {-20, -20, 20, 20}, {});
  CHECK(paths(below) == std::vector<DevicePath>{{{-1, -2}, {0, 1}, {-3, 0}, {-7, -7}}});
}

TEST_CASE("place: marks are strokes of the given half side, never out of the clip box") {
  Placed placed = place(drawing({}, {{0, 0}, {10, 10}}, 2), {}, {0, 0, 100, 100}, {});
  CHECK(placed.clipped);  // the mark at the origin sticks out
  REQUIRE(placed.paths.size() == 2);
  CHECK(path(placed, 1) == DevicePath{{8, 8}, {12, 8}, {12, 12}, {8, 12}, {8, 8}});
  for (auto p : path(placed, 0)) CHECK((p.x >= 0 && p.y >= 0));
  // The other shapes, and the device's point: a 12-bit screen has 4 units to the 4013 point.
  Drawing2 d;
  d.add_mark({50, 50}, MarkShape::cross, 2);
  d.add_mark({50, 50}, MarkShape::plus, 2);
  d.add_mark({50, 50}, MarkShape::diamond, 2);
  d.add_mark({50, 50}, MarkShape::circle, 2);
  Placed shapes = place(d, {}, {0, 0, 100, 100}, Rendering{.point = 4});
  REQUIRE(shapes.paths.size() == 2 + 2 + 1 + 1);
  CHECK(path(shapes, 0) == DevicePath{{42, 42}, {58, 58}});
  CHECK(path(shapes, 3) == DevicePath{{50, 42}, {50, 58}});
  CHECK(path(shapes, 4) == DevicePath{{50, 42}, {58, 50}, {50, 58}, {42, 50}, {50, 42}});
  for (auto p : path(shapes, 5)) CHECK(std::abs(std::hypot(p.x - 50, p.y - 50) - 8) <= 0.75);
}

TEST_CASE("place: curves are flattened in device units, more finely on a finer device") {
  // A quarter circle of radius 1 (rational quadratic), placed 100 times larger.
  Drawing2 d;
  const double controls[] = {1, 0, 1, 1, 0, 1};
  const double weights[] = {1, std::sqrt(0.5), 1};
  d.add_curve(2, Point2View(controls, 3), weights, {.pen = 2}, {Role::line, 1});
  const Placement at{100, 0, 0};
  Placed coarse = place(d, at, {-10, -10, 200, 200}, Rendering{.point = 1});
  Placed fine = place(d, at, {-10, -10, 200, 200}, Rendering{.point = 0.1});
  REQUIRE(coarse.paths.size() == 1);
  CHECK(coarse.styles[0].pen == 2);
  CHECK(path(coarse, 0).front() == DevicePoint{100, 0});
  CHECK(path(coarse, 0).back() == DevicePoint{0, 100});
  for (auto p : path(coarse, 0)) CHECK(std::abs(std::hypot(p.x, p.y) - 100) <= 1);
  CHECK(path(fine, 0).size() > path(coarse, 0).size());
}

TEST_CASE("render draws what place lists, in the same order, with the styles") {
  Drawing2 d = drawing({{{0, 0}, {10, 0}}, {{0, 5}, {10, 5}}}, {{5, 5}});
  d.add_text({1, 1}, "7", 1, {}, {Role::label, 7});
  const Placement at{2, 1, 1};
  Recorder r;
  CHECK_FALSE(render(d, at, {0, 0, 100, 100}, {}, r));
  Placed placed = place(d, at, {0, 0, 100, 100}, {});
  CHECK(r.drawn() == paths(placed));
  REQUIRE(r.texts.size() == 1);
  CHECK(r.texts[0].line == "7");
  CHECK(r.texts[0].at == DevicePoint{3, 3});
}

TEST_CASE("bounds: every finite point, read in parts on two threads in a large drawing") {
  // The box of a drawing against every point of every item read one by one: a small drawing,
  // then a grid shared as a surface image (its stringers not read again), with points that are
  // not finite and the extremes in its last rows, then a curve's controls and a mark.
  auto plain = [](const Drawing2& d) {
    const double inf = std::numeric_limits<double>::infinity();
    Box b{inf, inf, -inf, -inf};
    for (const auto& item : d.items())
      for (Point2 p : d.points(item))
        if (std::isfinite(p.x) && std::isfinite(p.y))
          b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
    return b;
  };
  auto same = [](const Box& a, const Box& b) {
    return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1;
  };
  CHECK(same(bounds(drawing({{{1, 2}, {std::nan(""), 9}, {3, -4}}, {{0.5, 7}}})),
             Box{0.5, -4, 3, 7}));
  CHECK(bounds(Drawing2{}).x0 > bounds(Drawing2{}).x1);  // nothing to hold
  const std::size_t planes = 420, rows = 400;
  for (int damage = 0; damage < 4; ++damage) {
    CAPTURE(damage);
    auto grid = grid_points(planes, rows, [](double c, double r) {
      return Point2{0.5 * r + 0.1 * c + 0.3 * std::sin(c * r), 0.4 * c - 0.05 * r};
    });
    const double inf = std::numeric_limits<double>::infinity();
    if (damage >= 1) (*grid)[2 * (419 * rows + 399)] = -inf;  // the last point
    if (damage >= 2) (*grid)[2 * (300 * rows + 20) + 1] = std::nan("");
    if (damage >= 3) (*grid)[2 * (211 * rows + 7)] = 1e300, (*grid)[2 * (417 * rows)] = -1e300;
    Drawing2 d = shared_grid(grid, planes, rows);
    const double controls[] = {10, 10, 60, 1200, 110, 10};
    d.add_curve(2, Point2View(controls, 3), {}, Style{2});
    d.add_mark({-40, 40}, MarkShape::cross, 3, Style{3});
    const Box got = bounds(d), want = plain(d);
    CHECK(same(got, want));
    CHECK(got.y1 == 1200);
    CHECK(got.x0 == (damage >= 3 ? -1e300 : -40));
  }
}

TEST_CASE("bounds: a shared grid's box, when it comes with the grid, stands for its points") {
  const std::size_t planes = 30, rows = 20;
  auto grid = grid_points(planes, rows, [](double c, double r) {
    return Point2{0.5 * r + 0.1 * c, 0.4 * c - 0.05 * r};
  });
  auto same = [](const Box& a, const Box& b) {
    return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1;
  };
  const Box read = bounds(shared_grid(grid, planes, rows));
  // A box other than the points' shows which one bounds took.
  const Drawing2::Extent told{-7, -8, 90, 91};
  auto with_box = [&](bool curves, bool stringers, std::size_t skip) {
    Drawing2 d;
    const auto pool = d.share(grid, grid->data(), grid->size(), told);
    for (std::size_t c = 0; curves && c < planes; ++c)
      if (c != skip) d.add_polyline(pool, 2 * c * rows, rows, 2);
    for (std::size_t r = 0; stringers && r < rows; ++r)
      d.add_polyline(pool, 2 * r, planes, 2 * rows);
    d.add_mark({100, 0}, MarkShape::cross, 3);  // a point of the drawing's own, read
    return bounds(d);
  };
  // The curves cover the grid: its box, the stringers not read, the mark added.
  CHECK(same(with_box(true, true, planes), Box{-7, -8, 100, 91}));
  CHECK(same(with_box(true, false, planes), Box{-7, -8, 100, 91}));
  // A curve missing, or the stringers alone: the points are read.
  CHECK(same(with_box(true, true, 4), Box{read.x0, read.y0, 100, read.y1}));
  CHECK(same(with_box(false, true, planes), Box{read.x0, read.y0, 100, read.y1}));
}

TEST_CASE("DeviceBox: the box of the points added, two at a time or one, and of boxes") {
  DeviceBox empty;
  CHECK(empty.empty());
  empty.add(std::span<const DevicePoint>{});
  CHECK(empty.empty());
  // Every count up to a few blocks of four, the extremes anywhere among the points.
  for (std::size_t n = 1; n < 19; ++n)
    for (std::size_t at = 0; at < n; ++at) {
      CAPTURE(n);
      CAPTURE(at);
      std::vector<DevicePoint> points;
      for (std::size_t i = 0; i < n; ++i)
        points.push_back({static_cast<int>(i * 7 % 5) - 2, static_cast<int>(i * 3 % 4)});
      points[at] = {std::numeric_limits<int>::min(), std::numeric_limits<int>::max()};
      if (n - 1 - at != at) points[n - 1 - at].x = 9;
      DeviceBox b;
      b.add(points);
      int x1 = std::numeric_limits<int>::min(), y0 = std::numeric_limits<int>::max();
      for (const DevicePoint p : points) x1 = std::max(x1, p.x), y0 = std::min(y0, p.y);
      CHECK(!b.empty());
      CHECK(b.x0 == std::numeric_limits<int>::min());
      CHECK(b.y1 == std::numeric_limits<int>::max());
      CHECK(b.x1 == x1);
      CHECK(b.y0 == y0);
    }
  DeviceBox a, b;
  a.add(std::vector<DevicePoint>{{1, 2}, {3, -4}});
  b.add(std::vector<DevicePoint>{{-5, 0}});
  a.add(b);
  a.add(DeviceBox{});  // an empty box changes nothing
  CHECK(a == DeviceBox{-5, -4, 3, 2});
}

TEST_CASE("place: the stringers of a shared grid, placed side by side, are the paths one by one") {
  // A grid of 40 curves of 37 points, shared by the drawing as a surface image is: its curves
  // one after another, its stringers a row apart (placed sixteen at a time). The same points
  // copied into a polyline each must give the same paths, styles and clipping, also when a
  // stringer has a point that is not finite, or one outside the clip box.
  const std::size_t planes = 40, rows = 37;
  for (int damage = 0; damage < 3; ++damage) {
    CAPTURE(damage);
    auto grid = grid_points(planes, rows, [](double c, double r) {
      return Point2{3.0 * r + 0.7 * c + 0.3 * std::sin(c * r), 2.0 * c + 0.4 * r};
    });
    if (damage == 1) (*grid)[2 * (11 * rows + 20)] = std::nan("");
    if (damage == 2) (*grid)[2 * (5 * rows + 19) + 1] = 1e4;
    Drawing2 shared, copied;
    const auto pool = shared.share(grid, grid->data(), grid->size());
    for (std::size_t c = 0; c < planes; ++c) {
      shared.add_polyline(pool, 2 * c * rows, rows, 2, {}, {Role::curve, int(c + 1)});
      copied.add_polyline(Point2View(grid->data() + 2 * c * rows, rows), {},
                          {Role::curve, int(c + 1)});
    }
    for (std::size_t r = 0; r < rows; ++r) {
      const Style style{1 + int(r % 2)};
      shared.add_polyline(pool, 2 * r, planes, 2 * rows, style, {Role::stringer, int(r + 1)});
      copied.add_polyline(Point2View(grid->data() + 2 * r, planes, 2 * rows), style,
                          {Role::stringer, int(r + 1)});
    }
    const Box clip{0, 0, 300, 200};
    const Placement at{2, 10, 5};
    const Placed a = place(shared, at, clip, {}), b = place(copied, at, clip, {});
    CHECK(paths(a) == paths(b));
    CHECK(a.styles == b.styles);
    CHECK(a.clipped == b.clipped);
    CHECK(a.clipped == (damage == 2));
    CHECK(a.paths.size() == planes + rows + (damage == 0 ? 0 : 2));
    CHECK(a.box == box_of_paths(a));
  }
}

}  // namespace igds::test::devices

namespace igds::test::devices {

namespace {

// Every polyline a device is given, as it is given, with its style.
struct PolylineRecorder : Device {
  std::vector<DevicePath> paths;
  std::vector<Style> styles;
  std::vector<std::pair<DevicePoint, std::string>> texts;
  Style current;
  void style(const Style& s) override { current = s; }
  void move(DevicePoint) override {}
  void draw(DevicePoint) override {}
  void polyline(std::span<const DevicePoint> points) override {
    paths.emplace_back(points.begin(), points.end());
    styles.push_back(current);
  }
  void text(DevicePoint p, std::string_view line) override { texts.emplace_back(p, line); }
  void page() override {}
};

}  // namespace

TEST_CASE("place: a large drawing placed in two parts at once is the drawing placed in order") {
  // A 420 x 400 grid shared as a surface image (curves, then stringers sixteen at a time), with a
  // point that is not finite and one outside the clip box in the second half, then a curve, marks
  // and texts: more points than one thread places alone. The same items placed one by one, each
  // a drawing of its own, give the paths in order; render() draws them.
  const std::size_t planes = 420, rows = 400;
  auto grid = grid_points(planes, rows, [](double c, double r) {
    return Point2{0.5 * r + 0.1 * c + 0.3 * std::sin(c * r), 0.4 * c + 0.05 * r};
  });
  (*grid)[2 * (300 * rows + 20)] = std::nan("");
  (*grid)[2 * (350 * rows + 19) + 1] = 1e4;
  Drawing2 d;
  const auto pool = d.share(grid, grid->data(), grid->size());
  for (std::size_t c = 0; c < planes; ++c)
    d.add_polyline(pool, 2 * c * rows, rows, 2, {}, {Role::curve, int(c + 1)});
  for (std::size_t r = 0; r < rows; ++r)
    d.add_polyline(pool, 2 * r, planes, 2 * rows, Style{1 + int(r % 3)},
                   {Role::stringer, int(r + 1)});
  const double controls[] = {10, 10, 60, 120, 110, 10};
  d.add_curve(2, Point2View(controls, 3), {}, Style{2});
  d.add_mark({40, 40}, MarkShape::cross, 3, Style{3});
  d.add_text({50, 50}, "INSIDE", 1);
  d.add_text({5000, 50}, "OUTSIDE", 1);
  const Box clip{0, 0, 400, 300};
  const Placement at{1.5, 5, 5};
  const Placed placed = place(d, at, clip, {});
  std::vector<DevicePath> one_by_one;
  std::vector<Style> styles;
  for (const auto& item : d.items()) {
    Drawing2 alone;
    const auto own = alone.share(grid, grid->data(), grid->size());
    if (item.pool != 0)
      alone.add_polyline(own, item.first, item.count, item.stride, item.style, item.id);
    else if (item.kind == Drawing2::Kind::curve)
      alone.add_curve(item.degree, d.points(item), {}, item.style);
    else if (item.kind == Drawing2::Kind::mark)
      alone.add_mark(d.points(item)[0], item.shape, item.size, item.style);
    const Placed p = place(alone, at, clip, {});
    for (std::size_t k = 0; k < p.paths.size(); ++k) {
      one_by_one.emplace_back(p.paths[k].begin(), p.paths[k].end());
      styles.push_back(p.styles[k]);
    }
  }
  CHECK(placed.clipped);
  CHECK(paths(placed) == one_by_one);
  CHECK(placed.styles == styles);
  CHECK(placed.paths.size() > planes + rows);
  // The box of the paths, measured as each part placed them (the plot order is given it).
  CHECK(!placed.box.empty());
  CHECK(placed.box == box_of_paths(placed));
  REQUIRE(placed.texts.size() == 1);
  CHECK(placed.texts[0].text == "INSIDE");
  PolylineRecorder r;
  CHECK(render(d, at, clip, {}, r));
  CHECK(r.paths == one_by_one);
  CHECK(r.styles == styles);
  REQUIRE(r.texts.size() == 1);
  CHECK(placed.texts[0].at == r.texts[0].first);
}
}  // namespace igds::test::devices

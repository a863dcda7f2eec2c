// The plot order (devices/plot_order.h) against the reference it replaced
// (tests/devices/plot_order_reference.h): the same paths, point for point, on every input.
#include "devices/plot_order.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <climits>
#include <random>

#include "tests/devices/plot_order_reference.h"

namespace igds::test::devices {

namespace {

using Paths = std::vector<DevicePath>;

// Both orders of `paths` from `start`, and both forms of the new one, must agree exactly.
void check_same(const Paths& paths, DevicePoint start) {
  Paths expected = reference::plot_order(paths, start);
  Paths got = plot_order(paths, start);
  REQUIRE(got == expected);
  PathList flat;
  flat.points.push_back({7, 7});  // whatever was there before is replaced
  plot_order(paths, start, flat);
  REQUIRE(flat.size() == expected.size());
  for (std::size_t k = 0; k < flat.size(); ++k)
    REQUIRE(DevicePath(flat[k].begin(), flat[k].end()) == expected[k]);
  // The strokes PLOT draws from: the same travel as the reference's paths.
  const std::vector<Line> lines(paths.begin(), paths.end());
  PlotOrder order;
  plot_order(lines, start, order);
  CHECK(order.size() == expected.size());
  CHECK(pen_up_travel(order, lines, start, {0, 0}) == pen_up_travel(expected, start, {0, 0}));
  // Given a box that holds the points, as PLOT gives the placement's (which may hold other
  // styles' paths too): the same strokes.
  DeviceBox box;
  for (const Line& line : lines) box.add(line);
  if (!box.empty()) {
    auto wider = [](int v, int by) {
      return static_cast<int>(
          std::clamp<long long>(static_cast<long long>(v) + by, INT_MIN, INT_MAX));
    };
    const DevicePoint corners[] = {{wider(box.x0, -3), wider(box.y0, -70)},
                                   {wider(box.x1, 12), wider(box.y1, 1)}};
    box.add(corners);
  }
  PlotOrder within;
  plot_order(lines, box, start, within);
  CHECK(within.starts == order.starts);
  REQUIRE(within.strokes.size() == order.strokes.size());
  for (std::size_t k = 0; k < order.strokes.size(); ++k) {
    const Stroke &a = within.strokes[k], &b = order.strokes[k];
    CHECK((a.line == b.line && a.first == b.first && a.last == b.last && a.reversed == b.reversed));
  }
}

// Polylines on a lattice of `side` x `side` points `step` apart: with few points, segments
// repeat in both directions, stand still (zero length) and meet three or more at a point.
Paths lattice_walks(std::mt19937& rng, int paths, int max_points, int side, int step) {
  std::uniform_int_distribution<int> coord(0, side - 1), len(1, max_points), dir(0, 8);
  Paths out;
  for (int k = 0; k < paths; ++k) {
    DevicePath p;
    int x = coord(rng), y = coord(rng);
    int n = len(rng);
    for (int i = 0; i < n; ++i) {
      p.push_back({x * step, y * step});
      int d = dir(rng);  // 8: stay (a zero-length segment)
      if (d < 8) {
        static constexpr int dx[] = {1, -1, 0, 0, 1, -1, 1, -1}, dy[] = {0, 0, 1, -1, 1, -1, -1, 1};
        x = std::clamp(x + dx[d], 0, side - 1), y = std::clamp(y + dy[d], 0, side - 1);
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}

// A wireframe of `nx` x `ny` cells drawn as the surface is (curves, then stringers), or patch
// by patch (every inner edge twice, the second time reversed), with some rows repeated.
Paths grid_like(std::mt19937& rng, int nx, int ny, bool patches) {
  std::uniform_int_distribution<int> step(1, 30), coin(0, 3);
  int sx = step(rng), sy = step(rng), ox = step(rng) - 15, oy = step(rng) - 15;
  auto at = [&](int i, int j) { return DevicePoint{ox + i * sx, oy + j * sy}; };
  Paths out;
  if (patches) {
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j)
        out.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), at(i, j)});
  } else {
    for (int j = 0; j <= ny; ++j) {
      DevicePath curve;
      for (int i = 0; i <= nx; ++i) curve.push_back(at(i, j));
      out.push_back(curve);
      if (coin(rng) == 0) out.push_back(DevicePath(curve.rbegin(), curve.rend()));
    }
    for (int i = 0; i <= nx; ++i) {
      DevicePath stringer;
      for (int j = 0; j <= ny; ++j) stringer.push_back(at(i, j));
      out.push_back(stringer);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("plot_order: the same paths as the reference on small lattice walks") {
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<int> any(-50, 50);
  for (int round = 0; round < 4000; ++round) {
    int side = 2 + round % 7, paths = 1 + round % 13;
    Paths p = lattice_walks(rng, paths, 1 + round % 9, side, 1 + round % 3);
    check_same(p, {any(rng), any(rng)});
  }
}

TEST_CASE("plot_order: the same paths as the reference on many pieces" *
          doctest::test_suite("slow")) {
  std::mt19937 rng(7);
  for (int round = 0; round < 40; ++round) {
    // Thousands of short walks: the grid of ends is used, and its plain search too.
    Paths p = lattice_walks(rng, 200 + 100 * round, 4, 30 + 10 * round, 1 + round % 5);
    check_same(p, {0, 0});
    check_same(p, {-1000, 5000});
  }
}

TEST_CASE("plot_order: the same paths as the reference on grids and patch wireframes" *
          doctest::test_suite("slow")) {
  std::mt19937 rng(99);
  for (int round = 0; round < 300; ++round) {
    std::uniform_int_distribution<int> n(1, 12);
    Paths p = grid_like(rng, n(rng), n(rng), round % 2 == 1);
    std::uniform_int_distribution<int> s(-100, 400);
    check_same(p, {s(rng), s(rng)});
    // The same drawn in reverse order: other pieces come first, other joins.
    std::reverse(p.begin(), p.end());
    check_same(p, {0, 0});
  }
  check_same(grid_like(rng, 150, 120, false), {0, 0});
  check_same(grid_like(rng, 60, 70, true), {5, 5});
  // More than 2^17 segments: the paths are cut into runs by two threads, the tiles shared by
  // them, and every inner edge of the wireframe is a repeat found in its tile.
  check_same(grid_like(rng, 400, 380, false), {3, 3});
  check_same(grid_like(rng, 200, 190, true), {0, 0});
  // More than 2^19 points: their box is found on two threads too.
  check_same(grid_like(rng, 600, 560, false), {1, 1});
}

TEST_CASE("plot_order: the same paths as the reference at the edges") {
  check_same({}, {0, 0});
  check_same({{}, {{3, 3}}, {{1, 1}, {1, 1}, {1, 1}}}, {0, 0});  // nothing with a length
  // A segment repeated, reversed, and cut by a zero-length one.
  check_same({{{0, 0}, {5, 0}}, {{5, 0}, {0, 0}}, {{0, 0}, {5, 0}, {5, 0}, {9, 0}}}, {0, 0});
  // Closed loops, a piece whose two ends meet, a star of four ends, ties in distance.
  check_same({{{0, 0}, {4, 0}, {4, 4}, {0, 0}}, {{10, 0}, {12, 2}, {10, 4}, {8, 2}, {10, 0}}},
             {10, 0});
  check_same({{{0, 0}, {5, 5}}, {{10, 0}, {5, 5}}, {{5, 5}, {5, 10}}, {{0, 10}, {5, 5}}}, {5, 5});
  check_same({{{-1, 0}, {-2, 0}}, {{1, 0}, {2, 0}}, {{0, 1}, {0, 2}}, {{0, -1}, {0, -2}}}, {0, 0});
  // Segments that share only their midpoint (their hashes are the same) are all drawn; a repeat
  // among them is not.
  const Paths midpoints{{{0, 0}, {4, 4}},  {{0, 4}, {4, 0}}, {{1, 2}, {3, 2}},
                        {{-2, 2}, {6, 2}}, {{4, 0}, {0, 4}}, {{2, -1}, {2, 5}}};
  check_same(midpoints, {0, 0});
  CHECK(plot_order(midpoints, {0, 0}).size() == 5);
  // Forty segments at one point, each drawn twice, the second time the other way round.
  Paths star;
  for (int k = 0; k < 40; ++k) star.push_back({{0, 0}, {k % 7 + 1, k / 7 - 3}});
  for (int k = 40; k-- > 0;) star.push_back({{k % 7 + 1, k / 7 - 3}, {0, 0}});
  check_same(star, {0, 0});
  // Coordinates far apart (ids too wide for one 64-bit segment key), and the extremes of int.
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> wide(-2000000000, 2000000000);
  for (int round = 0; round < 200; ++round) {
    Paths p = lattice_walks(rng, 1 + round % 20, 6, 5, 1 + round);
    for (auto& path : p)
      for (auto& q : path) q = {q.x * 100003 - 300000, q.y * 99991 + (round % 3) * 7};
    p.push_back({{wide(rng), wide(rng)}, {wide(rng), wide(rng)}});
    check_same(p, {wide(rng), wide(rng)});
  }
  check_same({{{INT_MIN, INT_MIN}, {INT_MAX, INT_MAX}, {INT_MIN, INT_MAX}, {INT_MIN, INT_MIN}},
              {{INT_MAX, INT_MAX}, {INT_MIN, INT_MIN}},
              {{0, 0}, {INT_MAX, INT_MIN}}},
             {0, 0});
}

}  // namespace igds::test::devices

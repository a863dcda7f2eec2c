// Hidden lines checked against a reference written here on its own: the surface's triangles
// drawn into a z-buffer four times finer than the kernel's raster, the nearness of each point
// found from the projection of the axes (or the eye's distance), every line sampled finely.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "tests/kernels/helpers.h"
#include "workspace/kernels/hidden.h"
#include "workspace/kernels/project.h"
#include "workspace/kernels/surface.h"

namespace igds {
namespace {

using test::Flat;

struct Seen {
  std::size_t planes, rows;
  Flat<Vec3> space;
  std::vector<double> xy, near;
};

// The reference's own nearness: the parallel projections' direction of sight from the images
// of the three axes (the screen seen from the eye's side is not mirrored); CONIC's 1 / depth.
std::vector<double> reference_nearness(const View& view, Vec3 centre, const Flat<Vec3>& pts) {
  std::vector<double> out(pts.size());
  if (view.projection == Projection::conic) {
    const Vec3 eye{view.parameters[0], view.parameters[1], view.parameters[2]};
    const Vec3 axis = centre - eye;
    const double d = norm(axis);
    for (std::size_t k = 0; k < pts.size(); ++k) out[k] = d * d / dot(pts[k] - eye, axis);
    return out;
  }
  Flat<Vec3> axes{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<double> img(8);
  project(view, centre, axes, MutablePoint2View(img.data(), 4));
  const Vec3 sx{img[2] - img[0], img[4] - img[0], img[6] - img[0]};
  const Vec3 sy{img[3] - img[1], img[5] - img[1], img[7] - img[1]};
  const Vec3 eye_side = cross(sx, sy);
  for (std::size_t k = 0; k < pts.size(); ++k) out[k] = dot(eye_side, pts[k]);
  return out;
}

Seen seen(std::size_t planes, std::size_t rows, Flat<Vec3> space, const View& view) {
  Seen s{planes, rows, std::move(space), {}, {}};
  const Vec3 centre = bounding_box_centre(s.space);
  s.xy.resize(2 * planes * rows);
  project(view, centre, s.space, MutablePoint2View(s.xy.data(), planes * rows));
  s.near = reference_nearness(view, centre, s.space);
  return s;
}

Seen seen(std::size_t planes, std::size_t rows, const std::function<Vec3(double, double)>& f,
          const View& view) {
  Flat<Vec3> space(planes * rows);
  for (std::size_t c = 0; c < planes; ++c)
    for (std::size_t r = 0; r < rows; ++r)
      space.set(c * rows + r, f(double(c) / double(planes - 1), double(r) / double(rows - 1)));
  return seen(planes, rows, std::move(space), view);
}

// The manual's example (its figure 6): a wave over 4 x 5 input points with its border tangents,
// interpolated with 4 curves and 4 stringers between each pair: 16 x 21 points.
Flat<Vec3> manual_wave() {
  const double z[4][5] = {{0, 5.657, 8, 5.657, 0},
                          {0, 4.333, 6.128, 4.333, 0},
                          {0, 0.982, 1.389, 0.982, 0},
                          {0, -2.828, -4, -2.828, 0}};
  Array inppn({20, 3});
  for (std::size_t c = 0; c < 4; ++c)
    for (std::size_t r = 0; r < 5; ++r) {
      double* p = inppn.data() + 3 * (5 * c + r);
      p[0] = 10.0 * double(r), p[1] = 10.0 * double(c), p[2] = z[c][r];
    }
  // Along the curves at their two ends, curve by curve; then along the stringers.
  const double rows[18][4] = {{0.847, 0, 0.532, 1},   {0.847, 0, -0.532, 5}, {0.901, 0, 0.434, 6},
                              {0.901, 0, -0.434, 10}, {0.994, 0, 0.108, 11}, {0.994, 0, -0.108, 15},
                              {0.954, 0, -0.3, 16},   {0.954, 0, 0.3, 20},   {0, 1, 0, 1},
                              {0, 1, 0, 16},          {0, 1, 0, 2},          {0, 0.946, -0.324, 17},
                              {0, 1, 0, 3},           {0, 0.9, -0.435, 18},  {0, 1, 0, 4},
                              {0, 0.946, -0.324, 19}, {0, 1, 0, 5},          {0, 1, 0, 20}};
  Array inptg({18, 4});
  for (std::size_t k = 0; k < 18; ++k)
    for (std::size_t i = 0; i < 4; ++i) inptg.data()[4 * k + i] = rows[k][i];
  const Surface s = interpolate({4, 5, 4, 4, &inppn, &inptg});
  REQUIRE(s.intpn.shape == std::vector<std::size_t>{16, 21, 3});
  Flat<Vec3> out(16 * 21);
  for (std::size_t k = 0; k < 16 * 21; ++k) out.set(k, Vec3::load(s.intpn.data() + 3 * k));
  return out;
}

// A z-buffer of the grid's triangles at the centres of cells of side `cell`, nearest kept, with
// the nearest triangle's change of nearness across a cell.
struct Reference {
  double x0, y0, cell;
  long nx, ny;
  std::vector<double> q, change;
  bool visible(double x, double y, double near, double tolerance) const {
    const long i = long(std::floor((x - x0) / cell)), j = long(std::floor((y - y0) / cell));
    if (i < 0 || j < 0 || i >= nx || j >= ny) return true;
    const double front = q[std::size_t(j * nx + i)];
    return near >= front - change[std::size_t(j * nx + i)] - tolerance;
  }
};

Reference reference(const Seen& s, double x0, double y0, double x1, double y1, double cell) {
  Reference z{x0, y0, cell, long(std::ceil((x1 - x0) / cell)), long(std::ceil((y1 - y0) / cell)),
              {}, {}};
  z.q.assign(std::size_t(z.nx * z.ny), -std::numeric_limits<double>::infinity());
  z.change.assign(z.q.size(), 0);
  auto tri = [&](std::size_t a, std::size_t b, std::size_t c) {
    const double ax = s.xy[2 * a], ay = s.xy[2 * a + 1], bx = s.xy[2 * b], by = s.xy[2 * b + 1],
                 cx = s.xy[2 * c], cy = s.xy[2 * c + 1];
    const double det = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
    if (std::abs(det) < 1e-300) return;
    const long i0 = std::max(0L, long(std::floor((std::min({ax, bx, cx}) - x0) / cell)));
    const long i1 = std::min(z.nx - 1, long(std::floor((std::max({ax, bx, cx}) - x0) / cell)));
    const long j0 = std::max(0L, long(std::floor((std::min({ay, by, cy}) - y0) / cell)));
    const long j1 = std::min(z.ny - 1, long(std::floor((std::max({ay, by, cy}) - y0) / cell)));
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i) {
        const double px = x0 + (double(i) + 0.5) * cell, py = y0 + (double(j) + 0.5) * cell;
        // Barycentric coordinates of the centre.
        const double l1 = ((px - ax) * (cy - ay) - (cx - ax) * (py - ay)) / det;
        const double l2 = ((bx - ax) * (py - ay) - (px - ax) * (by - ay)) / det;
        const double l0 = 1 - l1 - l2;
        if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9) continue;
        const double q = l0 * s.near[a] + l1 * s.near[b] + l2 * s.near[c];
        const std::size_t at = std::size_t(j * z.nx + i);
        if (q <= z.q[at]) continue;
        z.q[at] = q;
        // How far the triangle's nearness goes within a cell: its change over the cell's diagonal.
        const double gx =
            ((s.near[b] - s.near[a]) * (cy - ay) - (s.near[c] - s.near[a]) * (by - ay)) / det;
        const double gy =
            ((bx - ax) * (s.near[c] - s.near[a]) - (cx - ax) * (s.near[b] - s.near[a])) / det;
        z.change[at] = std::hypot(gx, gy) * cell * std::sqrt(2.0);
      }
  };
  for (std::size_t c = 0; c + 1 < s.planes; ++c)
    for (std::size_t r = 0; r + 1 < s.rows; ++r) {
      const std::size_t p00 = c * s.rows + r, p10 = p00 + s.rows, p11 = p10 + 1, p01 = p00 + 1;
      tri(p00, p10, p11);
      tri(p00, p11, p01);
    }
  return z;
}

// Compares the kernel's pieces with the reference: every drawn sample has a visible reference
// sample within one cell of the kernel's raster, and every visible reference sample has a drawn
// one as near. Returns the number of samples the reference finds hidden.
std::size_t compare(const Seen& s, int cells_across) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (std::size_t k = 0; k < s.planes * s.rows; ++k) {
    x0 = std::min(x0, s.xy[2 * k]), x1 = std::max(x1, s.xy[2 * k]);
    y0 = std::min(y0, s.xy[2 * k + 1]), y1 = std::max(y1, s.xy[2 * k + 1]);
  }
  const double cell = std::max(x1 - x0, y1 - y0) / cells_across;
  const SeenGrid grid{s.planes, s.rows, s.xy.data(), s.near.data()};
  const auto pieces = visible_pieces(grid, {x0, y0, x1, y1, cell});
  double lo = 1e300, hi = -1e300;
  for (double q : s.near) lo = std::min(lo, q), hi = std::max(hi, q);
  const Reference z = reference(s, x0, y0, x1, y1, cell / 4);

  // Every sample of every line, an eighth of a kernel cell apart along it.
  struct Sample {
    double x, y;
    bool drawn, visible;
    std::uint32_t line;
    double along;  // on the screen, from the line's start
  };
  std::vector<Sample> samples;
  for (std::uint32_t line = 0; line < s.planes + s.rows; ++line) {
    const bool curve = line < s.planes;
    const std::size_t n = curve ? s.rows : s.planes;
    auto at = [&](std::size_t k) {
      return curve ? line * s.rows + k : k * s.rows + (line - s.planes);
    };
    std::vector<VisiblePiece> mine;
    double walked = 0;
    for (const auto& p : pieces)
      if (p.line == line) mine.push_back(p);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const std::size_t a = at(k), b = at(k + 1);
      const double len = std::hypot(s.xy[2 * b] - s.xy[2 * a], s.xy[2 * b + 1] - s.xy[2 * a + 1]);
      const std::size_t m = std::max<std::size_t>(1, std::size_t(std::ceil(8 * len / cell)));
      for (std::size_t i = 0; i <= m; ++i) {
        const double f = double(i) / double(m), t = double(k) + f;
        const double x = s.xy[2 * a] + f * (s.xy[2 * b] - s.xy[2 * a]);
        const double y = s.xy[2 * a + 1] + f * (s.xy[2 * b + 1] - s.xy[2 * a + 1]);
        const double q = s.near[a] + f * (s.near[b] - s.near[a]);
        const bool drawn = std::any_of(mine.begin(), mine.end(), [t](const VisiblePiece& p) {
          return p.from <= t && t <= p.to;
        });
        samples.push_back(
            {x, y, drawn, z.visible(x, y, q, 1e-9 * (hi - lo)), line, walked + f * len});
      }
      walked += len;
    }
  }
  // What is seen: a drawn sample has a visible one within a kernel cell on the screen (of any
  // line: two lines drawn over each other look the same), and a visible one a drawn one.
  const long nx = long((x1 - x0) / cell) + 1;
  std::vector<std::vector<std::size_t>> drawn_at(std::size_t(nx * nx)), visible_at(drawn_at.size());
  auto bucket = [&](double x, double y) {
    return std::pair{std::clamp(long((x - x0) / cell), 0L, nx - 1),
                     std::clamp(long((y - y0) / cell), 0L, nx - 1)};
  };
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto [i, j] = bucket(samples[k].x, samples[k].y);
    if (samples[k].drawn) drawn_at[std::size_t(j * nx + i)].push_back(k);
    if (samples[k].visible) visible_at[std::size_t(j * nx + i)].push_back(k);
  }
  // Within a cell along the same line, or on the screen on another line.
  auto near_one = [&](const Sample& p, const std::vector<std::vector<std::size_t>>& of) {
    const auto [i, j] = bucket(p.x, p.y);
    for (long jj = std::max(0L, j - 1); jj <= std::min(nx - 1, j + 1); ++jj)
      for (long ii = std::max(0L, i - 1); ii <= std::min(nx - 1, i + 1); ++ii)
        for (std::size_t k : of[std::size_t(jj * nx + ii)]) {
          const Sample& o = samples[k];
          if (o.line == p.line ? std::abs(o.along - p.along) <= cell
                               : std::hypot(o.x - p.x, o.y - p.y) <= cell)
            return true;
        }
    return false;
  };
  std::size_t hidden = 0, drawn_not_visible = 0, visible_not_drawn = 0;
  for (const Sample& p : samples) {
    hidden += !p.visible;
    if (p.drawn && !near_one(p, visible_at)) ++drawn_not_visible;
    if (p.visible && !near_one(p, drawn_at)) ++visible_not_drawn;
  }
  MESSAGE(samples.size() << " samples, " << hidden
                         << " hidden; drawn, none visible near: " << drawn_not_visible
                         << "; visible, none drawn near: " << visible_not_drawn);
  CHECK(drawn_not_visible == 0);
  CHECK(visible_not_drawn == 0);
  // The surface hides something in most views: the check is not of lines all seen.
  return hidden;
}

const View views[] = {
    {Projection::orthogonal, {2, 0, 0}},
    {Projection::isometric, {3, 30, 0}},
    {Projection::assonometric, {110, 130, 120}},
    {Projection::conic, {3, -4, 2}},
};

Vec3 saddle(double u, double v) {
  const double x = 2 * u - 1, y = 2 * v - 1;
  return {x, y, x * x - y * y};
}

// A sheet folded back over itself: seen from most sides one part hides another.
Vec3 folded(double u, double v) {
  const double a = 1.5 * std::numbers::pi * u;
  return {std::cos(a) * (1 - 0.5 * u), 2 * v - 1, std::sin(a) * (1 - 0.5 * u) + 0.3 * v};
}

// A wave steep enough for its crests to hide its troughs from a low eye.
Vec3 wave(double u, double v) {
  return {2 * u - 1, 2 * v - 1, 0.4 * std::sin(9 * u) * std::cos(2 * v)};
}

TEST_CASE("hidden lines: the kernel's pieces agree with a z-buffer four times finer") {
  const std::pair<std::string, Vec3 (*)(double, double)> surfaces[] = {
      {"saddle", saddle}, {"folded", folded}, {"wave", wave}};
  std::size_t hidden = 0;
  for (const auto& surface : surfaces)
    for (const View& view : views) {
      CAPTURE(surface.first);
      CAPTURE(static_cast<int>(view.projection));
      const Seen s = seen(41, 37, surface.second, view);
      hidden += compare(s, 256);
    }
  CHECK(hidden > 100000);
}

TEST_CASE("hidden lines: the manual's wave agrees with the finer z-buffer, from a low eye too") {
  const View wave_views[] = {
      {Projection::orthogonal, {2, 0, 0}},
      {Projection::isometric, {3, 30, 0}},
      {Projection::assonometric, {110, 130, 120}},
      {Projection::conic, {80, -20, 14}},
  };
  std::size_t hidden = 0;
  for (const View& view : wave_views) {
    CAPTURE(static_cast<int>(view.projection));
    hidden += compare(seen(16, 21, manual_wave(), view), 256);
  }
  CHECK(hidden > 1000);
}

// A sheet folded as a Z: a floor (z 0, x 0 to 1), a slope back up to x 0.4, a roof (z 1, x 0.4
// to 1.6). From above the roof hides the slope and the floor beyond x 0.4.
Vec3 zed(double u, double v) {
  const double y = 2 * v - 1;
  if (u <= 0.4) return {u / 0.4, y, 0};
  if (u <= 0.6) return {1 - 3 * (u - 0.4), y, 5 * (u - 0.4)};
  return {0.4 + 3 * (u - 0.6), y, 1};
}

TEST_CASE("hidden lines: the Z's floor is seen to x 0.4, its slope not at all, its roof whole") {
  const View above[] = {{Projection::orthogonal, {1, 0, 0}}, {Projection::conic, {0.8, 0.1, 60}}};
  for (const View& view : above) {
    const Seen s = seen(51, 11, zed, view);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (std::size_t k = 0; k < s.planes * s.rows; ++k) {
      x0 = std::min(x0, s.xy[2 * k]), x1 = std::max(x1, s.xy[2 * k]);
      y0 = std::min(y0, s.xy[2 * k + 1]), y1 = std::max(y1, s.xy[2 * k + 1]);
    }
    const SeenGrid grid{s.planes, s.rows, s.xy.data(), s.near.data()};
    const auto pieces = visible_pieces(grid, {x0, y0, x1, y1, std::max(x1 - x0, y1 - y0) / 512});
    // Along a stringer a point step is 0.05 in x on the floor: a cell is under a tenth of one.
    // The floor is seen to where the line to the eye passes the roof's edge, x 0.4 at z 1.
    const double within = 0.1;
    const double ex = view.parameters[0], ez = view.parameters[2];
    const double floor_end =
        (view.projection == Projection::conic ? (0.4 - ex / ez) / (1 - 1 / ez) : 0.4) / 0.05;
    // The two border stringers lie on the roof's edges: seen or not, within a cell.
    std::vector<VisiblePiece> stringers;
    for (const auto& p : pieces)
      if (p.line > 51 && p.line < 61) stringers.push_back(p);
    REQUIRE(stringers.size() == 18);
    for (std::size_t k = 0; k < 18; k += 2) {
      CHECK(stringers[k].from == 0);
      CHECK(std::abs(stringers[k].to - floor_end) < within);
      CHECK(std::abs(stringers[k + 1].from - 30) < within);
      CHECK(stringers[k + 1].to == 50);
    }
    // Curves: those of the floor to x 0.4 and of the roof whole, the others not at all (but for
    // a cell where they meet the roof's edge); curves 8 and 30 lie under the roof's edge.
    for (std::uint32_t c = 0; c < 51; ++c) {
      if (c == 8 || c == 30) continue;
      double drawn = 0;
      for (const auto& p : pieces)
        if (p.line == c) drawn += p.to - p.from;
      CAPTURE(c);
      if (c <= 7 || c >= 31)
        CHECK(drawn == 10);
      else
        CHECK(drawn < within);
    }
  }
}

TEST_CASE("hidden lines: a surface seen with nothing in front of it hides none of its lines") {
  // The saddle from straight above: every line lies on the surface, none behind it.
  const Seen s = seen(30, 30, saddle, {Projection::orthogonal, {1, 0, 0}});
  const SeenGrid grid{s.planes, s.rows, s.xy.data(), s.near.data()};
  const auto pieces = visible_pieces(grid, {-1, -1, 1, 1, 2.0 / 1024});
  REQUIRE(pieces.size() == 60);
  for (const auto& p : pieces) {
    CHECK(p.from == 0);
    CHECK(p.to == 29);
  }
}

TEST_CASE("hidden lines: the folded sheet hides part of itself, and from the other side too") {
  for (double side : {1.0, -1.0}) {
    const Seen s = seen(41, 21, folded, {Projection::conic, {6 * side, 0.3, 0.4}});
    const SeenGrid grid{s.planes, s.rows, s.xy.data(), s.near.data()};
    auto pieces = visible_pieces(grid, {-10, -10, 10, 10, 20.0 / 1024});
    double drawn = 0;
    for (const auto& p : pieces) drawn += p.to - p.from;
    const double all = 41.0 * 20 + 21.0 * 40;
    CHECK(drawn < 0.95 * all);
    CHECK(drawn > 0.3 * all);
  }
}

TEST_CASE("hidden lines: points that are not finite break their lines and hide nothing") {
  Seen s = seen(5, 5, saddle, {Projection::orthogonal, {1, 0, 0}});
  s.xy[2 * 12] = std::numeric_limits<double>::quiet_NaN();
  const SeenGrid grid{s.planes, s.rows, s.xy.data(), s.near.data()};
  const auto pieces = visible_pieces(grid, {-1, -1, 1, 1, 0.01});
  // Curve 2 and stringer 2 (through point 2 2) break there: two pieces each, the others whole.
  CHECK(pieces.size() == 12);
  CHECK(pieces[2] == VisiblePiece{2, 0, 1});
  CHECK(pieces[3] == VisiblePiece{2, 3, 4});
}

TEST_CASE("hidden lines: the raster has at most max_raster_cells across") {
  const Seen s = seen(4, 4, saddle, {Projection::orthogonal, {1, 0, 0}});
  const SeenGrid grid{s.planes, s.rows, s.xy.data(), s.near.data()};
  // A cell a millionth of the picture: the kernel takes 4096 instead (else 10^12 cells).
  CHECK(visible_pieces(grid, {-1, -1, 1, 1, 2e-6}).size() == 8);
}

}  // namespace
}  // namespace igds

#include "workspace/kernels/hidden.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "workspace/kernels/interrupt.h"
#include "workspace/kernels/parallel.h"

namespace igds {

void nearness(const View& view, Vec3 centre, Vec3View points, std::span<double> out) {
  if (out.size() != points.size()) throw std::length_error("nearness: output size differs");
  const ProjectiveMap map = projection_map(view, centre);
  const auto& m = map.m;
  if (map.perspective) {
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vec3 p = points[k];
      out[k] = 1 / (m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
    }
    return;
  }
  // The direction every point of a line of sight shares is what the projection drops (the
  // cross product of its two rows); the screen seen from its side is not mirrored.
  const Vec3 towards_eye = cross(Vec3{m[0][0], m[0][1], m[0][2]}, Vec3{m[1][0], m[1][1], m[1][2]});
  for (std::size_t k = 0; k < points.size(); ++k) out[k] = dot(towards_eye, points[k]);
}

namespace {

constexpr float nothing = -std::numeric_limits<float>::infinity();

// A triangle's nearness on the screen: its gradient per cell, and how much it changes within a
// cell: across the cell's diagonal, or its whole range when that is smaller (a triangle seen
// nearly edge on is steep on the screen but thin in depth). `change` is negative for a triangle
// seen edge on (or not finite), which covers no cell's centre.
struct Slope {
  double gu = 0, gv = 0;
  float change = -1;
};

// Triangle a b c in cell coordinates u v, with nearness q.
inline Slope slope_of_triangle(const double* a, const double* b, const double* c) {
  const double e1u = b[0] - a[0], e1v = b[1] - a[1], e2u = c[0] - a[0], e2v = c[1] - a[1];
  const double area = e1u * e2v - e2u * e1v;
  if (!(std::abs(area) > 1e-12)) return {};
  const double dq1 = b[2] - a[2], dq2 = c[2] - a[2], per_area = 1 / area;
  Slope s{(dq1 * e2v - dq2 * e1v) * per_area, (e1u * dq2 - e2u * dq1) * per_area};
  const double range = std::max({a[2], b[2], c[2]}) - std::min({a[2], b[2], c[2]});
  const double change = std::min(std::sqrt(2 * (s.gu * s.gu + s.gv * s.gv)), range);
  if (std::isfinite(change)) s.change = static_cast<float>(change);
  return s;
}

// The least whole number at or above x, and the greatest at or below, for 0 <= x < 2^52.
std::ptrdiff_t up(double x) {
  const auto n = static_cast<std::ptrdiff_t>(x);
  return double(n) < x ? n + 1 : n;
}
std::ptrdiff_t down(double x) {
  return static_cast<std::ptrdiff_t>(x);
}

// The nearest surface at the centre of each cell, and how fast the nearness of the triangle that
// is nearest there changes across the screen (per cell), to tell a point on that triangle from
// one behind it.
class DepthBuffer {
 public:
  DepthBuffer(const Raster& r, double reference)
      : r_(r),
        reference_(reference),
        nx_(std::max<std::ptrdiff_t>(1, std::ptrdiff_t(std::ceil((r.x1 - r.x0) / r.cell)))),
        ny_(std::max<std::ptrdiff_t>(1, std::ptrdiff_t(std::ceil((r.y1 - r.y0) / r.cell)))),
        tiles_x_((nx_ + tile - 1) / tile),
        cells_(std::size_t(tiles_x_ * tile * ((ny_ + tile - 1) / tile) * tile),
               Cell{nothing, 0.f}) {}

  std::ptrdiff_t rows() const { return ny_; }

  // The cell coordinates of a point: cell (i, j) has its centre at (i, j).
  double u(double x) const { return (x - r_.x0) / r_.cell - 0.5; }
  double v(double y) const { return (y - r_.y0) / r_.cell - 0.5; }

  // Triangle a b c (cell coordinates u v and nearness q) of slope `slope`, only its cells of
  // rows [j0, j1).
  void add(const double* a, const double* b, const double* c, const Slope& slope, std::ptrdiff_t j0,
           std::ptrdiff_t j1) {
    if (slope.change < 0) return;
    const double umin = std::min({a[0], b[0], c[0]}), umax = std::max({a[0], b[0], c[0]}),
                 vmin = std::min({a[1], b[1], c[1]}), vmax = std::max({a[1], b[1], c[1]});
    if (umax < 0 || umin > double(nx_ - 1) || vmax < double(j0) || vmin > double(j1 - 1)) return;
    const std::ptrdiff_t i_lo = up(std::max(umin, 0.0)),
                         i_hi = down(std::min(umax, double(nx_ - 1)));
    const std::ptrdiff_t j_lo = up(std::max(vmin, double(j0)));
    const std::ptrdiff_t j_hi = down(std::min(vmax, double(j1 - 1)));
    const double gu = slope.gu, gv = slope.gv;
    const double e1u = b[0] - a[0], e1v = b[1] - a[1], e2u = c[0] - a[0], e2v = c[1] - a[1];
    const double area = e1u * e2v - e2u * e1v;
    // A centre on an edge belongs to both triangles: no crack between them.
    const double s = area > 0 ? 1 : -1, slack = -1e-9 * std::abs(area);
    for (std::ptrdiff_t j = j_lo; j <= j_hi; ++j)
      for (std::ptrdiff_t i = i_lo; i <= i_hi; ++i) {
        const double pu = double(i) - a[0], pv = double(j) - a[1];
        const double w1 = s * (pu * e2v - pv * e2u), w2 = s * (e1u * pv - e1v * pu);
        if (w1 < slack || w2 < slack || w1 + w2 > s * area - slack) continue;
        const float q = static_cast<float>(a[2] + gu * pu + gv * pv - reference_);
        const std::size_t at = index(i, j);
        if (q > cells_[at].near) cells_[at] = {q, slope.change};
      }
  }

  // True when a point at cell coordinates u v of nearness q, on a line whose own triangles
  // change by `own` within a cell, is hidden by more than `tolerance` plus what the surface
  // changes within a cell.
  bool hidden(double u, double v, double q, float own, double tolerance) const {
    // Cell (i, j) holds the points within half a cell of its centre.
    const double fi = u + 0.5, fj = v + 0.5;
    if (!(fi >= 0 && fj >= 0 && fi < double(nx_) && fj < double(ny_))) return false;
    const std::size_t at = index(std::ptrdiff_t(fi), std::ptrdiff_t(fj));
    const Cell cell = cells_[at];
    if (cell.near == nothing) return false;
    const float front = cell.near;
    const double within = double(std::max(cell.change, own));
    return q - reference_ < double(front) - within - tolerance;
  }

  // Cells in tiles of 8 x 8 (512 bytes): a line crossing the raster in any direction, and the
  // next line beside it, read a few tiles rather than a cache line per cell.
  static constexpr std::ptrdiff_t tile = 8;

 private:
  std::size_t index(std::ptrdiff_t i, std::ptrdiff_t j) const {
    return std::size_t((((j / tile) * tiles_x_ + i / tile) * tile + j % tile) * tile + i % tile);
  }

  Raster r_;
  double reference_;
  std::ptrdiff_t nx_, ny_, tiles_x_;
  // Side by side: a sample reads both at once.
  struct Cell {
    float near, change;
  };
  std::vector<Cell> cells_;
};

}  // namespace

std::vector<VisiblePiece> visible_pieces(const SeenGrid& g, const Raster& given) {
  std::vector<VisiblePiece> pieces;
  const std::size_t planes = g.planes, rows = g.rows, count = planes * rows;
  if (count == 0) return pieces;
  Raster raster = given;
  const double side = std::max(raster.x1 - raster.x0, raster.y1 - raster.y0);
  if (!(raster.cell > 0) || !std::isfinite(raster.cell) || !std::isfinite(side)) raster.cell = 1;
  if (side / raster.cell > max_raster_cells) raster.cell = side / max_raster_cells;
  if (!(side > 0)) raster.x1 = raster.x0 + raster.cell, raster.y1 = raster.y0 + raster.cell;

  // The tolerance from the data: a millionth of the nearness's range, well above the rounding of
  // a float against the middle of that range (kept in the buffer less that middle).
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t k = 0; k < count; ++k)
    if (std::isfinite(g.near[k])) lo = std::min(lo, g.near[k]), hi = std::max(hi, g.near[k]);
  if (!(lo <= hi)) lo = hi = 0;
  const double reference = lo / 2 + hi / 2, tolerance = 1e-6 * (hi - lo);

  DepthBuffer depth(raster, reference);
  auto corner = [&](std::size_t c, std::size_t r, double* out) {
    const std::size_t k = c * rows + r;
    out[0] = depth.u(g.xy[2 * k]), out[1] = depth.v(g.xy[2 * k + 1]), out[2] = g.near[k];
  };
  // How much the nearness of quadrilateral (c, r)'s triangles changes within a cell (the
  // larger), found while the raster is filled.
  const std::size_t quad_rows = rows - 1;
  std::vector<float> quad_change((planes - 1) * quad_rows);
  // Each thread fills its own band of rows of cells and looks at every quadrilateral.
  const unsigned threads = threads_for(count);
  in_parallel(threads, [&](unsigned t) {
    // Whole rows of tiles each.
    const std::ptrdiff_t bands = (depth.rows() + DepthBuffer::tile - 1) / DepthBuffer::tile;
    const std::ptrdiff_t j0 = bands * t / threads * DepthBuffer::tile,
                         j1 = std::min(depth.rows(), bands * (t + 1) / threads * DepthBuffer::tile);
    // This thread's planes of quadrilaterals get their slopes kept (quad_change).
    const std::size_t own_from = (planes - 1) * t / threads,
                      own_to = (planes - 1) * (t + 1) / threads;
    double p00[3], p10[3], p11[3], p01[3];
    for (std::size_t c = 0; c + 1 < planes; ++c) {
      if (t == 0) check_interrupt();
      const bool own = c >= own_from && c < own_to;
      for (std::size_t r = 0; r + 1 < rows; ++r) {
        corner(c, r, p00), corner(c + 1, r, p10), corner(c + 1, r + 1, p11), corner(c, r + 1, p01);
        const double vlo = std::min({p00[1], p10[1], p11[1], p01[1]});
        const double vhi = std::max({p00[1], p10[1], p11[1], p01[1]});
        const bool in_band = vhi >= double(j0) - 1 && vlo <= double(j1);
        if (!in_band && !own) continue;
        const Slope first = slope_of_triangle(p00, p10, p11),
                    second = slope_of_triangle(p00, p11, p01);
        if (own) quad_change[c * quad_rows + r] = std::max({0.f, first.change, second.change});
        if (!in_band) continue;
        depth.add(p00, p10, p11, first, j0, j1);
        depth.add(p00, p11, p01, second, j0, j1);
      }
    }
  });

  auto slope_of = [&](std::ptrdiff_t c, std::ptrdiff_t r) {
    if (c < 0 || r < 0 || std::size_t(c) + 1 >= planes || std::size_t(r) + 1 >= rows) return 0.f;
    return quad_change[std::size_t(c) * quad_rows + std::size_t(r)];
  };

  // What a line's walk knows between its segments.
  struct Walk {
    bool open = false;    // a visible piece has begun, at `start`
    bool joined = false;  // the last segment ended at this one's first point, `joined_visible`
    bool joined_visible = false;
    double start = 0;
  };
  auto see = [](Walk& w, std::uint32_t line, bool visible, double at,
                std::vector<VisiblePiece>& out) {
    if (visible && !w.open) w.open = true, w.start = at;
    if (!visible && w.open) {
      w.open = false;
      if (at > w.start) out.push_back({line, w.start, at});
    }
  };
  // Segment k of line `line`, from point ia to point ib, with the quadrilaterals beside it.
  auto segment = [&](Walk& w, std::uint32_t line, std::size_t k, std::size_t ia, std::size_t ib,
                     float own, std::vector<VisiblePiece>& out) {
    const double ax = depth.u(g.xy[2 * ia]), ay = depth.v(g.xy[2 * ia + 1]),
                 bx = depth.u(g.xy[2 * ib]), by = depth.v(g.xy[2 * ib + 1]), qa = g.near[ia],
                 qb = g.near[ib];
    if (!(std::isfinite(ax) && std::isfinite(ay) && std::isfinite(bx) && std::isfinite(by) &&
          std::isfinite(qa) && std::isfinite(qb))) {
      see(w, line, false, double(k), out);
      w.joined = false;
      return;
    }
    // Samples a cell apart at most: visibility changes halfway between two that differ, within
    // half a cell of where it does.
    const double length = std::sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
    const double steps = std::min(std::ceil(length), 2 * max_raster_cells);
    const std::size_t m = std::max<std::size_t>(1, std::size_t(steps));
    double previous_t = 0;
    bool previous = false;
    for (std::size_t s = 0; s <= m; ++s) {
      const double t = double(s) / double(m);
      // The first sample is the previous segment's last one.
      const bool visible = s == 0 && w.joined
                               ? w.joined_visible
                               : !depth.hidden(ax + t * (bx - ax), ay + t * (by - ay),
                                               qa + t * (qb - qa), own, tolerance);
      if (s == 0)
        see(w, line, visible, double(k), out);
      else if (visible != previous)
        see(w, line, visible, double(k) + (previous_t + t) / 2, out);
      previous = visible, previous_t = t;
    }
    w.joined = true, w.joined_visible = previous;
  };
  // The curves one by one (their points are consecutive); the stringers in blocks side by side,
  // plane by plane, so that each plane's points of a block are read together.
  constexpr std::size_t block = 64;
  const std::size_t blocks = (rows + block - 1) / block, jobs = planes + blocks;
  const unsigned parts = threads_for(count);
  std::vector<std::vector<VisiblePiece>> found(parts);
  in_parallel(parts, [&](unsigned t) {
    std::vector<VisiblePiece>& out = found[t];
    std::vector<Walk> walks(block);
    for (std::size_t job = jobs * t / parts; job < jobs * (t + 1) / parts; ++job) {
      if (t == 0 && job % 64 == 0) check_interrupt();
      if (job < planes) {
        const auto line = static_cast<std::uint32_t>(job);
        Walk w;
        for (std::size_t k = 0; k + 1 < rows; ++k)
          segment(w, line, k, job * rows + k, job * rows + k + 1,
                  std::max(slope_of(std::ptrdiff_t(job) - 1, std::ptrdiff_t(k)),
                           slope_of(std::ptrdiff_t(job), std::ptrdiff_t(k))),
                  out);
        see(w, line, false, double(rows - 1), out);
        continue;
      }
      const std::size_t r0 = (job - planes) * block, r1 = std::min(rows, r0 + block);
      const std::size_t first = out.size();
      std::fill(walks.begin(), walks.end(), Walk{});
      for (std::size_t k = 0; k + 1 < planes; ++k)
        for (std::size_t r = r0; r < r1; ++r)
          segment(walks[r - r0], static_cast<std::uint32_t>(planes + r), k, k * rows + r,
                  (k + 1) * rows + r,
                  std::max(slope_of(std::ptrdiff_t(k), std::ptrdiff_t(r) - 1),
                           slope_of(std::ptrdiff_t(k), std::ptrdiff_t(r))),
                  out);
      for (std::size_t r = r0; r < r1; ++r)
        see(walks[r - r0], static_cast<std::uint32_t>(planes + r), false, double(planes - 1), out);
      // Each stringer's pieces together, in order along it.
      std::stable_sort(
          out.begin() + std::ptrdiff_t(first), out.end(),
          [](const VisiblePiece& a, const VisiblePiece& b) { return a.line < b.line; });
    }
  });
  for (auto& part : found) pieces.insert(pieces.end(), part.begin(), part.end());
  return pieces;
}

}  // namespace igds

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
        near_(std::size_t(nx_ * ny_), nothing),
        slope_(std::size_t(nx_ * ny_), 0.f) {}

  std::ptrdiff_t rows() const { return ny_; }

  // The cell coordinates of a point: cell (i, j) has its centre at (i, j).
  double u(double x) const { return (x - r_.x0) / r_.cell - 0.5; }
  double v(double y) const { return (y - r_.y0) / r_.cell - 0.5; }

  // Triangle a b c (cell coordinates u v and nearness q), only its cells of rows [j0, j1).
  void add(const double* a, const double* b, const double* c, std::ptrdiff_t j0,
           std::ptrdiff_t j1) {
    const double e1u = b[0] - a[0], e1v = b[1] - a[1], e2u = c[0] - a[0], e2v = c[1] - a[1];
    const double area = e1u * e2v - e2u * e1v;
    if (!(std::abs(area) > 1e-12)) return;  // seen edge on (or not finite): it covers no centre
    const double dq1 = b[2] - a[2], dq2 = c[2] - a[2];
    const double gu = (dq1 * e2v - dq2 * e1v) / area, gv = (e1u * dq2 - e2u * dq1) / area;
    // How much its nearness changes within a cell: across the diagonal, or its whole range when
    // it is smaller (a triangle seen nearly edge on is steep on the screen but thin in depth).
    const double range = std::max({a[2], b[2], c[2]}) - std::min({a[2], b[2], c[2]});
    const float slope = static_cast<float>(std::min(std::sqrt(2.0) * std::hypot(gu, gv), range));
    const std::ptrdiff_t i_lo =
        std::max<std::ptrdiff_t>(0, std::ptrdiff_t(std::ceil(std::min({a[0], b[0], c[0]}))));
    const std::ptrdiff_t i_hi =
        std::min<std::ptrdiff_t>(nx_ - 1, std::ptrdiff_t(std::floor(std::max({a[0], b[0], c[0]}))));
    const std::ptrdiff_t j_lo =
        std::max<std::ptrdiff_t>(j0, std::ptrdiff_t(std::ceil(std::min({a[1], b[1], c[1]}))));
    const std::ptrdiff_t j_hi =
        std::min<std::ptrdiff_t>(j1 - 1, std::ptrdiff_t(std::floor(std::max({a[1], b[1], c[1]}))));
    // A centre on an edge belongs to both triangles: no crack between them.
    const double s = area > 0 ? 1 : -1, slack = -1e-9 * std::abs(area);
    for (std::ptrdiff_t j = j_lo; j <= j_hi; ++j)
      for (std::ptrdiff_t i = i_lo; i <= i_hi; ++i) {
        const double pu = double(i) - a[0], pv = double(j) - a[1];
        const double w1 = s * (pu * e2v - pv * e2u), w2 = s * (e1u * pv - e1v * pu);
        if (w1 < slack || w2 < slack || w1 + w2 > s * area - slack) continue;
        const float q = static_cast<float>(a[2] + gu * pu + gv * pv - reference_);
        const std::size_t at = std::size_t(j * nx_ + i);
        if (q > near_[at]) near_[at] = q, slope_[at] = slope;
      }
  }

  // True when a point at x y of nearness q, on a line whose own triangles change by `own` per
  // cell, is hidden by more than `tolerance` plus what the surface changes within a cell.
  bool hidden(double x, double y, double q, float own, double tolerance) const {
    const double fi = std::floor((x - r_.x0) / r_.cell), fj = std::floor((y - r_.y0) / r_.cell);
    if (!(fi >= 0 && fj >= 0 && fi < double(nx_) && fj < double(ny_))) return false;
    const std::size_t at = std::size_t(std::ptrdiff_t(fj) * nx_ + std::ptrdiff_t(fi));
    const float front = near_[at];
    if (front == nothing) return false;
    const double within = double(std::max(slope_[at], own));
    return q - reference_ < double(front) - within - tolerance;
  }

 private:
  Raster r_;
  double reference_;
  std::ptrdiff_t nx_, ny_;
  std::vector<float> near_, slope_;
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
  // Each thread fills its own band of rows of cells and looks at every quadrilateral.
  const unsigned threads = threads_for(count);
  in_parallel(threads, [&](unsigned t) {
    const std::ptrdiff_t j0 = depth.rows() * t / threads, j1 = depth.rows() * (t + 1) / threads;
    double p00[3], p10[3], p11[3], p01[3];
    for (std::size_t c = 0; c + 1 < planes; ++c) {
      if (t == 0) check_interrupt();
      for (std::size_t r = 0; r + 1 < rows; ++r) {
        corner(c, r, p00), corner(c + 1, r, p10), corner(c + 1, r + 1, p11), corner(c, r + 1, p01);
        const double vlo = std::min({p00[1], p10[1], p11[1], p01[1]});
        const double vhi = std::max({p00[1], p10[1], p11[1], p01[1]});
        if (!(vhi >= double(j0) - 1 && vlo <= double(j1))) continue;
        depth.add(p00, p10, p11, j0, j1);
        depth.add(p00, p11, p01, j0, j1);
      }
    }
  });

  // How fast the nearness of quadrilateral (c, r)'s triangles changes, per cell (0 outside).
  auto slope_of = [&](std::ptrdiff_t c, std::ptrdiff_t r) {
    if (c < 0 || r < 0 || std::size_t(c) + 1 >= planes || std::size_t(r) + 1 >= rows) return 0.f;
    double p[4][3];
    corner(std::size_t(c), std::size_t(r), p[0]), corner(std::size_t(c) + 1, std::size_t(r), p[1]);
    corner(std::size_t(c) + 1, std::size_t(r) + 1, p[2]),
        corner(std::size_t(c), std::size_t(r) + 1, p[3]);
    float most = 0;
    for (const auto& tri : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
      const double *a = p[tri[0]], *b = p[tri[1]], *cc = p[tri[2]];
      const double e1u = b[0] - a[0], e1v = b[1] - a[1], e2u = cc[0] - a[0], e2v = cc[1] - a[1];
      const double area = e1u * e2v - e2u * e1v;
      if (!(std::abs(area) > 1e-12)) continue;
      const double dq1 = b[2] - a[2], dq2 = cc[2] - a[2];
      const double range = std::max({a[2], b[2], cc[2]}) - std::min({a[2], b[2], cc[2]});
      const double s = std::min(std::sqrt(2.0) * std::hypot((dq1 * e2v - dq2 * e1v) / area,
                                                            (e1u * dq2 - e2u * dq1) / area),
                                range);
      if (std::isfinite(s)) most = std::max(most, static_cast<float>(s));
    }
    return most;
  };

  // Line `line`'s pieces: its points k = 0 .. n-1 are (plane, row) = at(k).
  auto walk = [&](std::uint32_t line, std::vector<VisiblePiece>& out) {
    const bool curve = line < planes;
    const std::size_t n = curve ? rows : planes, fixed = curve ? line : line - planes;
    auto index = [&](std::size_t k) { return curve ? fixed * rows + k : k * rows + fixed; };
    bool open = false;
    double start = 0;
    auto see = [&](bool visible, double at) {
      if (visible && !open) open = true, start = at;
      if (!visible && open) {
        open = false;
        if (at > start) out.push_back({line, start, at});
      }
    };
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const std::size_t ia = index(k), ib = index(k + 1);
      const double ax = g.xy[2 * ia], ay = g.xy[2 * ia + 1], bx = g.xy[2 * ib],
                   by = g.xy[2 * ib + 1], qa = g.near[ia], qb = g.near[ib];
      if (!(std::isfinite(ax) && std::isfinite(ay) && std::isfinite(bx) && std::isfinite(by) &&
            std::isfinite(qa) && std::isfinite(qb))) {
        see(false, double(k));
        continue;
      }
      // The triangles the segment is an edge of.
      const auto c = std::ptrdiff_t(curve ? fixed : k), r = std::ptrdiff_t(curve ? k : fixed);
      const float own = curve ? std::max(slope_of(c - 1, r), slope_of(c, r))
                              : std::max(slope_of(c, r - 1), slope_of(c, r));
      // Samples half a cell apart at most (a long segment: only where it crosses the raster);
      // visibility changes halfway between two samples that differ.
      const double length = std::hypot(bx - ax, by - ay);
      const double steps = std::min(std::ceil(2 * length / raster.cell), 4 * max_raster_cells);
      const std::size_t m = std::max<std::size_t>(1, std::size_t(steps));
      double previous_t = 0;
      bool previous = false;
      for (std::size_t s = 0; s <= m; ++s) {
        const double t = double(s) / double(m);
        const bool visible = !depth.hidden(ax + t * (bx - ax), ay + t * (by - ay),
                                           qa + t * (qb - qa), own, tolerance);
        if (s == 0) {
          see(visible, double(k));
        } else if (visible != previous) {
          see(visible, double(k) + (previous_t + t) / 2);
        }
        previous = visible, previous_t = t;
      }
    }
    see(false, double(n - 1));
  };

  const std::uint32_t lines = static_cast<std::uint32_t>(planes + rows);
  const unsigned parts = threads_for(count);
  std::vector<std::vector<VisiblePiece>> found(parts);
  in_parallel(parts, [&](unsigned t) {
    const std::uint32_t first = lines * t / parts, last = lines * (t + 1) / parts;
    for (std::uint32_t line = first; line < last; ++line) {
      if (t == 0 && line % 64 == 0) check_interrupt();
      walk(line, found[t]);
    }
  });
  for (auto& part : found) pieces.insert(pieces.end(), part.begin(), part.end());
  return pieces;
}

}  // namespace igds

#include "workspace/exchange/surface_curves.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "workspace/kernels/coons.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"
#include "workspace/kernels/memory.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/spline.h"

namespace igds {

namespace {

void require_grid(const SurfaceInput& in) {
  if (in.nocur < 2 || in.nostr < 2) throw DataError(DataError::Problem::grid_too_small);
  if (in.intcu < 0 || in.intst < 0) throw DataError(DataError::Problem::negative_density);
}

void require_patches(const SurfaceInput& in, const Array& patches) {
  require_grid(in);
  require_shape("PATCHES", &patches,
                {std::size_t(in.nocur) - 1, std::size_t(in.nostr) - 1, 3, 4, 4});
}

// The Hermite weights F0 F1 G0 G1 at a/(inserted+1), a = 0..inserted+1, as FIT computes them.
std::vector<Hermite> blending(int inserted) {
  std::vector<Hermite> w(std::size_t(inserted) + 2);
  for (std::size_t a = 0; a < w.size(); ++a) w[a] = hermite(double(a) / double(inserted + 1));
  return w;
}

// Row r of a patch's M (per coordinate k: m[16k + 4r + c]) combined with the weights of the
// other direction: the Hermite coefficient r of an iso-line v = const.
Vec3 row_at(const double* m, int r, const Hermite& h) {
  double v[3];
  for (int k = 0; k < 3; ++k) {
    const double* row = m + 16 * k + 4 * r;
    v[k] = row[0] * h.f0 + row[1] * h.f1 + row[2] * h.g0 + row[3] * h.g1;
  }
  return {v[0], v[1], v[2]};
}

// Column c likewise: the Hermite coefficient c of an iso-line u = const.
Vec3 column_at(const double* m, int c, const Hermite& h) {
  double v[3];
  for (int k = 0; k < 3; ++k) {
    const double* col = m + 16 * k + c;
    v[k] = col[0] * h.f0 + col[4] * h.f1 + col[8] * h.g0 + col[12] * h.g1;
  }
  return {v[0], v[1], v[2]};
}

// A third of a derivative, divided as the net divides it (surface_net), so both give the same
// bits for the input curves.
Vec3 third(Vec3 d) {
  return {d.x / 3, d.y / 3, d.z / 3};
}

// The border ring of the input grid (as DISPLAY INPUT draws it): curve 1, the last stringer, the
// last curve backwards, the first stringer backwards.
std::vector<double> border_ring(const SurfaceInput& in) {
  const std::size_t nc = in.nocur, ns = in.nostr;
  const double* p = in.inppn->data();
  std::vector<double> ring;
  auto add = [&](std::size_t i, std::size_t j) {
    ring.insert(ring.end(), p + 3 * (i * ns + j), p + 3 * (i * ns + j) + 3);
  };
  for (std::size_t j = 0; j < ns; ++j) add(0, j);
  for (std::size_t i = 1; i < nc; ++i) add(i, ns - 1);
  for (std::size_t j = ns - 1; j-- > 0;) add(nc - 1, j);
  for (std::size_t i = nc - 1; --i > 0;) add(i, 0);
  return ring;
}

void add_input(Drawing3& d, const SurfaceInput& in) {
  const Style pen2{.pen = input_pen};
  const std::vector<double> ring = border_ring(in);
  d.add_polyline(Vec3View(ring.data(), ring.size() / 3), pen2, {Role::border, 0}, true);

  // Tangent lines: the longest is a quarter of the largest extent of the input points.
  const Vec3View points = as_vec3(*in.inppn);
  Vec3 lo = points[0], hi = points[0];
  for (Vec3 p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const std::size_t nc = in.nocur, ns = in.nostr, rows = 2 * (nc + ns);
  double longest = 0;
  for (std::size_t r = 0; r < rows; ++r)
    longest = std::max(longest, norm(border_tangent(*in.inptg, r)));
  if (longest > 0 && std::isfinite(longest)) {
    const double scale = 0.25 * (extent > 0 ? extent : longest) / longest;
    for (std::size_t r = 0; r < rows; ++r) {
      const Vec3 t = border_tangent(*in.inptg, r);
      if (norm(t) == 0) continue;
      // INPTG's row order (workspace/state.h): curve ends first, then stringer ends.
      const bool along_curve = r < 2 * nc;
      const std::size_t k = along_curve ? (r / 2) * ns + (r % 2 == 0 ? 0 : ns - 1)
                                        : (r % 2 == 0 ? 0 : nc - 1) * ns + (r - 2 * nc) / 2;
      const Vec3 base = points[k], tip = base + scale * t;
      const double line[6] = {base.x, base.y, base.z, tip.x, tip.y, tip.z};
      d.add_polyline(Vec3View(line, 2), pen2, {Role::tangent, int(k + 1), along_curve ? 1 : 0});
    }
  }
  for (std::size_t k = 0; k < points.size(); ++k)
    d.add_mark(points[k], MarkShape::square, input_mark_size, pen2, {Role::point, int(k + 1)});
}

}  // namespace

Drawing3 surface_curves(const SurfaceInput& in, const Surface& surface) {
  return surface_curves(in, surface.patches, surface.intpn);
}

Drawing3 surface_curves(const SurfaceInput& in, const Array& patches_array,
                        const Array& intpn_array) {
  require_patches(in, patches_array);
  const std::size_t nc = in.nocur, ns = in.nostr, ic = in.intcu, is = in.intst;
  const GridShape g = intpn_shape(in.nocur, in.nostr, in.intcu, in.intst);
  require_shape("INTPN", &intpn_array, {g.rows, g.cols, 3});
  require_shape("INPPN", in.inppn, {nc * ns, 3});
  require_shape("INPTG", in.inptg, {2 * (nc + ns), 4});

  const std::vector<Hermite> wv = blending(in.intcu), wu = blending(in.intst);
  const double* patches = patches_array.data();
  const double* intpn = intpn_array.data();
  auto grid = [&](std::size_t row, std::size_t col) {
    return Vec3::load(intpn + 3 * (row * g.cols + col));
  };
  auto patch = [&](std::size_t i, std::size_t j) { return patches + (i * (ns - 1) + j) * 48; };

  Drawing3 d;
  // Room for every item at once: the curves' and stringers' controls, then add_input's border
  // ring, tangent lines (two points each) and a mark per input point.
  const std::size_t ends = 2 * (nc + ns);
  d.reserve(g.rows + g.cols + 1 + ends + nc * ns,
            g.rows * (3 * (ns - 1) + 1) + g.cols * (3 * (nc - 1) + 1) + 3 * ends + nc * ns);
  std::vector<double> controls(3 * (3 * (std::max(nc, ns) - 1) + 1));
  // Curve I: the iso-line v = b/(INTCU+1) of patch row i, one span per patch column; its
  // derivatives along u are rows 2 and 3 of M weighted by the v blending (docs/exchange.md).
  for (std::size_t row = 0; row < g.rows; ++row) {
    const std::size_t i = std::min(row / (ic + 1), nc - 2);
    const Hermite& h = wv[row - i * (ic + 1)];
    for (std::size_t j = 0; j + 1 < ns; ++j) {
      const double* m = patch(i, j);
      const Vec3 p0 = grid(row, j * (is + 1)), p1 = grid(row, (j + 1) * (is + 1));
      const Vec3 d0 = row_at(m, 2, h), d1 = row_at(m, 3, h);
      p0.store(&controls[9 * j]);
      (p0 + third(d0)).store(&controls[9 * j + 3]);
      (p1 - third(d1)).store(&controls[9 * j + 6]);
      p1.store(&controls[9 * j + 9]);
    }
    d.add_curve(3, Vec3View(controls.data(), 3 * (ns - 1) + 1), {}, {},
                {Role::curve, int(row + 1)});
  }
  // Stringer J: the iso-line u = a/(INTST+1) of patch column j; derivatives along v are columns
  // 2 and 3 of M weighted by the u blending.
  for (std::size_t col = 0; col < g.cols; ++col) {
    const std::size_t j = std::min(col / (is + 1), ns - 2);
    const Hermite& h = wu[col - j * (is + 1)];
    for (std::size_t i = 0; i + 1 < nc; ++i) {
      const double* m = patch(i, j);
      const Vec3 p0 = grid(i * (ic + 1), col), p1 = grid((i + 1) * (ic + 1), col);
      const Vec3 d0 = column_at(m, 2, h), d1 = column_at(m, 3, h);
      p0.store(&controls[9 * i]);
      (p0 + third(d0)).store(&controls[9 * i + 3]);
      (p1 - third(d1)).store(&controls[9 * i + 6]);
      p1.store(&controls[9 * i + 9]);
    }
    d.add_curve(3, Vec3View(controls.data(), 3 * (nc - 1) + 1), {}, {},
                {Role::stringer, int(col + 1)});
  }
  add_input(d, in);
  return d;
}

BezierNet surface_net(const SurfaceInput& in, const Array& patches) {
  require_patches(in, patches);
  const std::size_t nc = in.nocur, ns = in.nostr;
  BezierNet net;
  net.rows = 3 * (nc - 1) + 1;
  net.cols = 3 * (ns - 1) + 1;
  reserve_large(net.xyz, 3 * net.rows * net.cols);
  net.xyz.resize(3 * net.rows * net.cols);
  // Patch (i, j) makes rows 3i .. 3i + 2 and columns 3j .. 3j + 2 of its controls, and its last
  // row or column too when it is the last patch that has it: each control is made once, by the
  // last patch in row order that holds it, and patch rows can be made on threads of their own.
  std::vector<double> row_largest(nc - 1);
  parallel_for(nc - 1, threads_for(net.xyz.size()), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      const int vs = i + 2 == nc ? 4 : 3;
      double largest = 0;
      for (std::size_t j = 0; j + 1 < ns; ++j) {
        const int as = j + 2 == ns ? 4 : 3;
        const double* m = patches.data() + (i * (ns - 1) + j) * 48;
        for (int k = 0; k < 3; ++k) {
          const double* mk = m + 16 * k;
          // Hermite to Bézier along u (rows of M: P(0,.), P(1,.), Pu(0,.), Pu(1,.)), then along
          // v: controls P, P + D/3, P - D/3, P with the chord-scaled derivatives D
          // (docs/exchange.md).
          double g[4][4];
          for (int c = 0; c < 4; ++c) {
            g[0][c] = mk[c];
            g[1][c] = mk[c] + mk[8 + c] / 3;
            g[2][c] = mk[4 + c] - mk[12 + c] / 3;
            g[3][c] = mk[4 + c];
          }
          for (int a = 0; a < as; ++a) {
            const double b[4] = {g[a][0], g[a][0] + g[a][2] / 3, g[a][1] - g[a][3] / 3, g[a][1]};
            for (int v = 0; v < vs; ++v) {
              const std::size_t row = 3 * i + std::size_t(v), col = 3 * j + std::size_t(a);
              net.xyz[3 * (row * net.cols + col) + std::size_t(k)] = b[v];
              // A value that is not finite (NaN too) counts as infinite.
              const double magnitude = std::abs(b[v]) <= DBL_MAX ? std::abs(b[v]) : HUGE_VAL;
              largest = std::max(largest, magnitude);
            }
          }
        }
      }
      row_largest[i] = largest;
    }
  });
  net.largest = *std::max_element(row_largest.begin(), row_largest.end());
  return net;
}

namespace {

// The B-spline of the Bézier controls first[0], first[stride], ... (count of them, x y z each),
// read where they are in the net.
std::optional<CubicBspline> bspline_of(const double* first, std::size_t stride, std::size_t count) {
  std::vector<Vec3> b;  // the Bézier controls of the spans kept
  std::vector<double> t;
  const std::size_t spans = (count - 1) / 3;
  b.reserve(count);
  t.reserve(spans + 1);
  auto point = [&](std::size_t k) { return Vec3::load(first + k * stride); };
  for (std::size_t s = 0; s < spans; ++s) {
    const double length = chord_length(point(3 * s), point(3 * s + 3));
    if (!(length > 0)) continue;
    if (b.empty()) {
      b.push_back(point(0));
      t.push_back(0);
    }
    for (std::size_t k = 1; k <= 3; ++k) b.push_back(point(3 * s + k));
    t.push_back(t.back() + length);
  }
  if (b.empty()) return std::nullopt;
  const std::size_t n = t.size() - 1;  // spans
  CubicBspline out;
  out.controls.resize(n + 3);
  out.controls[0] = b[0];
  for (std::size_t k = 0; k < n; ++k) {
    const double before = k == 0 ? 0 : t[k] - t[k - 1], here = t[k + 1] - t[k];
    out.controls[k + 1] = b[3 * k + 1] - (before / here) * (b[3 * k + 2] - b[3 * k + 1]);
  }
  out.controls[n + 1] = b[3 * n - 1];
  out.controls[n + 2] = b[3 * n];
  out.knots = std::move(t);
  out.multiplicities.assign(n + 1, 1);
  out.multiplicities.front() = out.multiplicities.back() = 4;
  return out;
}

}  // namespace

std::optional<CubicBspline> input_curve_bspline(const BezierNet& net, std::size_t i) {
  return bspline_of(&net.xyz[3 * (3 * i) * net.cols], 3, net.cols);
}

std::optional<CubicBspline> input_stringer_bspline(const BezierNet& net, std::size_t j) {
  return bspline_of(&net.xyz[3 * (3 * j)], 3 * net.cols, net.rows);
}

std::vector<std::optional<CubicBspline>> input_bsplines(const BezierNet& net) {
  const std::size_t nc = (net.rows - 1) / 3 + 1, ns = (net.cols - 1) / 3 + 1;
  std::vector<std::optional<CubicBspline>> out(nc + ns);
  // The curves, then the stringers, each cut between the threads (a stringer's controls are far
  // apart in the net, a curve's side by side).
  const unsigned threads = threads_for(net.xyz.size());
  parallel_for(nc, threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) out[i] = input_curve_bspline(net, i);
  });
  parallel_for(ns, threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t j = first; j < last; ++j) out[nc + j] = input_stringer_bspline(net, j);
  });
  return out;
}

}  // namespace igds

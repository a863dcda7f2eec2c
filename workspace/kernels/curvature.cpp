#include "workspace/kernels/curvature.h"

#include <algorithm>
#include <vector>

#include "workspace/kernels/coons.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/spline.h"

namespace igds {

namespace {

// The Hermite blending functions of docs/kernels.md and their first and second derivatives at s.
struct Blend {
  double f[4], d1[4], d2[4];
};
Blend blend(double s) {
  const Hermite h = hermite(s);
  const double s2 = s * s;
  return {{h.f0, h.f1, h.g0, h.g1},
          {6 * s2 - 6 * s, -6 * s2 + 6 * s, 3 * s2 - 4 * s + 1, 3 * s2 - 2 * s},
          {12 * s - 6, -12 * s + 6, 6 * s - 4, 6 * s - 2}};
}

// Grid line `index` of `count` in a direction with `inputs` input lines and `inserted` lines
// between each two: its patch and its parameter in that patch, as FIT places it.
struct Place {
  std::size_t patch;
  double s;
};
Place place(std::size_t index, std::size_t inputs, std::size_t inserted) {
  const std::size_t step = inserted + 1;
  const std::size_t patch = std::min(index / step, inputs - 2);
  return {patch, double(index - patch * step) / double(step)};
}

// a0 F0(s) + a1 F1(s) + a2 G0(s) + a3 G1(s) (docs/kernels.md) as c0 + c1 s + c2 s^2 + c3 s^3.
struct Cubic {
  double c0, c1, c2, c3;
};
Cubic cubic(const double a[4]) {
  return {a[0], a[2], 3 * (a[1] - a[0]) - 2 * a[2] - a[3], 2 * (a[0] - a[1]) + a[2] + a[3]};
}

// The curvature vectors of the points at u[0..n) of a patch: six numbers a point, into `out`
// (u runs along the curves, v along the stringers).
void patch_curvature(const CurvatureRows::Polynomials& p, const double* u, std::size_t n,
                     double* out) {
  for (std::size_t m = 0; m < n; ++m) {
    const double s = u[m];
    double du[3], duu[3], dv[3], dvv[3];
    for (int c = 0; c < 3; ++c) {
      du[c] = (p.du[2][c] * s + p.du[1][c]) * s + p.du[0][c];
      duu[c] = p.duu[1][c] * s + p.duu[0][c];
      dv[c] = ((p.dv[3][c] * s + p.dv[2][c]) * s + p.dv[1][c]) * s + p.dv[0][c];
      dvv[c] = ((p.dvv[3][c] * s + p.dvv[2][c]) * s + p.dvv[1][c]) * s + p.dvv[0][c];
    }
    curvature_vector({du[0], du[1], du[2]}, {duu[0], duu[1], duu[2]}).store(out + 6 * m);
    curvature_vector({dv[0], dv[1], dv[2]}, {dvv[0], dvv[1], dvv[2]}).store(out + 6 * m + 3);
  }
}

// A single curve or stringer: the spline of its points, arc by arc.
Array line_curvature(const SurfaceInput& in) {
  const std::size_t n_points = std::size_t(in.nocur) * std::size_t(in.nostr);
  require_shape("INPPN", in.inppn, {n_points, 3});
  require_shape("INPTG", in.inptg, {2 * (std::size_t(in.nocur) + std::size_t(in.nostr)), 4});
  const LineSpline line = line_spline(in);
  const bool curve = line.curve;
  const std::size_t n = line.points.size(), count = line.count();
  const Vec3View points = line.points;
  const std::vector<Vec3>& tangents = line.tangents;
  Array out(curve ? std::vector<std::size_t>{1, count, 6} : std::vector<std::size_t>{count, 1, 6});
  for (std::size_t k = 0; k < count; ++k) {
    const Place at = place(k, n, line.inserted);
    const Vec3 p0 = points[at.patch], p1 = points[at.patch + 1];
    const double length = chord_length(p0, p1);
    const Vec3 t0 = length * tangents[at.patch], t1 = length * tangents[at.patch + 1];
    const Blend b = blend(at.s);
    const Vec3 d1 = b.d1[0] * p0 + b.d1[1] * p1 + b.d1[2] * t0 + b.d1[3] * t1;
    const Vec3 d2 = b.d2[0] * p0 + b.d2[1] * p1 + b.d2[2] * t0 + b.d2[3] * t1;
    curvature_vector(d1, d2).store(out.data() + 6 * k + (curve ? 0 : 3));
  }
  return out;
}

}  // namespace

Vec3 curvature_vector(Vec3 d1, Vec3 d2) {
  const double speed2 = dot(d1, d1);
  if (speed2 == 0) return {};  // a derivative that is not finite makes one that is not
  const double inverse = 1 / speed2;
  return inverse * (d2 - (dot(d2, d1) * inverse) * d1);
}

CurvatureRows::CurvatureRows(const SurfaceInput& in, const Array& patches,
                             const PatchSource* source)
    : in_(in),
      patches_(patches),
      source_(source),
      cols_(intpn_shape(in.nocur, in.nostr, in.intcu, in.intst).cols),
      patches_in_row_(std::size_t(in.nostr) - 1),
      step_(std::size_t(in.intst) + 1),
      column_u_(step_ + 1),
      made_(source ? 48 * patches_in_row_ : 0),
      polynomials_(patches_in_row_) {
  if (!source)
    require_shape("PATCHES", &patches,
                  {std::size_t(in.nocur) - 1, std::size_t(in.nostr) - 1, 3, 4, 4});
  for (std::size_t k = 0; k <= step_; ++k) column_u_[k] = double(k) / double(step_);
}

void CurvatureRows::operator()(std::size_t first, std::size_t last, double* out) {
  const std::size_t pc = patches_in_row_;
  for (std::size_t i = first; i < last; ++i) {
    const Place row = place(i, std::size_t(in_.nocur), std::size_t(in_.intcu));
    const Blend v = blend(row.s);
    if (source_ && made_row_ != row.patch) {
      (void)coons_patch_row(*source_, row.patch, made_.data());  // finite: the surface was made
      made_row_ = row.patch;
    }
    const double* patch_row = source_ ? made_.data() : patches_.data() + 48 * row.patch * pc;
    for (std::size_t j = 0; j < pc; ++j) {
      const double* m = patch_row + 48 * j;
      Polynomials& p = polynomials_[j];
      for (int c = 0; c < 3; ++c) {
        // a = M v-blends: the point's curve is a0 F0(u) + a1 F1(u) + a2 G0(u) + a3 G1(u).
        double a[3][4];
        for (int r = 0; r < 4; ++r) {
          const double* mr = m + 16 * c + 4 * r;
          for (int b = 0; b < 3; ++b) {
            const double* w = b == 0 ? v.f : b == 1 ? v.d1 : v.d2;
            a[b][r] = mr[0] * w[0] + mr[1] * w[1] + mr[2] * w[2] + mr[3] * w[3];
          }
        }
        const Cubic curve = cubic(a[0]), along = cubic(a[1]), bend = cubic(a[2]);
        p.du[0][c] = curve.c1, p.du[1][c] = 2 * curve.c2, p.du[2][c] = 3 * curve.c3;
        p.duu[0][c] = 2 * curve.c2, p.duu[1][c] = 6 * curve.c3;
        p.dv[0][c] = along.c0, p.dv[1][c] = along.c1, p.dv[2][c] = along.c2;
        p.dv[3][c] = along.c3;
        p.dvv[0][c] = bend.c0, p.dvv[1][c] = bend.c1, p.dvv[2][c] = bend.c2;
        p.dvv[3][c] = bend.c3;
      }
    }
    // Every patch's columns: `step` of them, one more (u = 1) in the last patch.
    double* o = out + 6 * cols_ * (i - first);
    for (std::size_t j = 0; j < pc; ++j) {
      const std::size_t n = j + 1 < pc ? step_ : step_ + 1;
      patch_curvature(polynomials_[j], column_u_.data(), n, o + 6 * step_ * j);
    }
  }
}

Array grid_curvature(const SurfaceInput& in, const Array& patches) {
  if (in.nocur == 1 || in.nostr == 1) return line_curvature(in);
  const GridShape shape = intpn_shape(in.nocur, in.nostr, in.intcu, in.intst);
  require_shape("PATCHES", &patches,
                {std::size_t(in.nocur) - 1, std::size_t(in.nostr) - 1, 3, 4, 4});
  Array out = Array::for_output({shape.rows, shape.cols, 6});  // every number written below
  parallel_for(shape.rows, threads_for(shape.rows * shape.cols * 6),
               [&](std::size_t first, std::size_t last) {
                 CurvatureRows(in, patches)(first, last, out.data() + 6 * shape.cols * first);
               });
  return out;
}

}  // namespace igds

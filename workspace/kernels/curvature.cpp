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

void store(double* out, Vec3 v) {
  v.store(out);
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
    store(out.data() + 6 * k + (curve ? 0 : 3), curvature_vector(d1, d2));
  }
  return out;
}

}  // namespace

Vec3 curvature_vector(Vec3 d1, Vec3 d2) {
  const double speed2 = dot(d1, d1);
  if (!(speed2 > 0)) return {};
  return (1 / speed2) * (d2 - (dot(d2, d1) / speed2) * d1);
}

void grid_curvature_rows(const SurfaceInput& in, const Array& patches, std::size_t first,
                         std::size_t last, double* out, const PatchSource* source) {
  const GridShape shape = intpn_shape(in.nocur, in.nostr, in.intcu, in.intst);
  if (!source)
    require_shape("PATCHES", &patches,
                  {std::size_t(in.nocur) - 1, std::size_t(in.nostr) - 1, 3, 4, 4});
  const std::size_t pc = std::size_t(in.nostr) - 1;
  // The blending functions of every column once: the rows share them.
  std::vector<Blend> columns(shape.cols);
  std::vector<std::size_t> column_patch(shape.cols);
  for (std::size_t j = 0; j < shape.cols; ++j) {
    const Place at = place(j, std::size_t(in.nostr), std::size_t(in.intst));
    columns[j] = blend(at.s);
    column_patch[j] = at.patch;
  }
  // A row of patch matrices made from `source` when it is needed, in `made`.
  std::vector<double> made(source ? pc * 48 : 0);
  std::size_t made_row = std::size_t(-1);
  // Per patch of the row, M times v's blends and their derivatives, per coordinate: then each
  // point costs four products of length 4 per coordinate.
  std::vector<double> mv(pc * 3 * 3 * 4);
  for (std::size_t i = first; i < last; ++i) {
    const Place row = place(i, std::size_t(in.nocur), std::size_t(in.intcu));
    const Blend v = blend(row.s);
    if (source && made_row != row.patch) {
      (void)coons_patch_row(*source, row.patch, made.data());  // finite: the surface was made
      made_row = row.patch;
    }
    const double* patch_row = source ? made.data() : patches.data() + 48 * row.patch * pc;
    for (std::size_t j = 0; j < pc; ++j) {
      const double* m = patch_row + 48 * j;
      double* out_j = mv.data() + 36 * j;
      for (const double* b : {v.f, v.d1, v.d2}) {
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 4; ++r, ++out_j) {
            const double* mr = m + 16 * c + 4 * r;
            *out_j = mr[0] * b[0] + mr[1] * b[1] + mr[2] * b[2] + mr[3] * b[3];
          }
      }
    }
    double* o = out + 6 * shape.cols * (i - first);
    for (std::size_t j = 0; j < shape.cols; ++j, o += 6) {
      const Blend& u = columns[j];
      const double* f = mv.data() + 36 * column_patch[j];  // M F(v)
      const double *f1 = f + 12, *f2 = f + 24;             // M F'(v), M F''(v)
      auto times = [](const double* a, const double* mb) {
        double x[3];
        for (int c = 0; c < 3; ++c)
          x[c] =
              a[0] * mb[4 * c] + a[1] * mb[4 * c + 1] + a[2] * mb[4 * c + 2] + a[3] * mb[4 * c + 3];
        return Vec3{x[0], x[1], x[2]};
      };
      // u runs along the curves, v along the stringers (docs/kernels.md).
      store(o, curvature_vector(times(u.d1, f), times(u.d2, f)));
      store(o + 3, curvature_vector(times(u.f, f1), times(u.f, f2)));
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
                 grid_curvature_rows(in, patches, first, last, out.data() + 6 * shape.cols * first);
               });
  return out;
}

}  // namespace igds

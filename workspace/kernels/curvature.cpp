#include "workspace/kernels/curvature.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "workspace/kernels/conic_lanes.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/processor.h"
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

// Every lane (processor.h) is computed with the operations the scalar code uses, in its order,
// and without fused multiply-adds, so that the curvature is the same bit for bit on every
// processor: curvature_vector for each lane. (Results through a reference: a vector returned by
// value would change the calling convention with the processor's instructions.)
[[gnu::always_inline]] inline void curvature_lanes(const Vec3Lanes& d1, const Vec3Lanes& d2,
                                                   Vec3Lanes& k) {
  const Lanes speed2 = d1.x * d1.x + d1.y * d1.y + d1.z * d1.z;
  const LaneMask direction = speed2 != 0;  // zero where the curve has no direction
  const Lanes inverse = 1 / speed2;
  const Lanes along = (d2.x * d1.x + d2.y * d1.y + d2.z * d1.z) * inverse;
  k.x = Lanes(LaneMask(inverse * (d2.x - along * d1.x)) & direction);
  k.y = Lanes(LaneMask(inverse * (d2.y - along * d1.y)) & direction);
  k.z = Lanes(LaneMask(inverse * (d2.z - along * d1.z)) & direction);
}

// The curve's and the stringer's curvature vectors of Pu, Puu, Pv and Pvv (d[0..3], per
// coordinate).
[[gnu::always_inline]] inline void curvatures(const Lanes d[4][3], Vec3Lanes& along,
                                              Vec3Lanes& across) {
  curvature_lanes({d[0][0], d[0][1], d[0][2]}, {d[1][0], d[1][1], d[1][2]}, along);
  curvature_lanes({d[2][0], d[2][1], d[2][2]}, {d[3][0], d[3][1], d[3][2]}, across);
}

// The image of a vector k by the linear part of a parallel projection's map (rows 0 and 1 of
// ProjectiveMap::m): numbers or lanes alike.
template <class T>
[[gnu::always_inline]] inline void linear_image(const double (&r)[3][4], const T& x, const T& y,
                                                const T& z, T& X, T& Y) {
  X = r[0][0] * x + r[0][1] * y + r[0][2] * z;
  Y = r[1][0] * x + r[1][1] * y + r[1][2] * z;
}

// Per coordinate, the polynomials in u of a patch's curve's first and second derivatives, then of
// its stringer's (the curves of the first and second derivatives in v), lowest power first.
template <class T>
struct PolynomialsOf {
  T du[3][3], duu[2][3], dv[4][3], dvv[4][3];
};
using Polynomials = PolynomialsOf<double>;

// The polynomials of patch matrix `m` (coons.h) on the grid line at v, whose Hermite blends and
// their derivatives are lanes 0, 1 and 2 of w[k] (the k-th of each).
[[gnu::always_inline]] inline void polynomials(const double* m, const Lanes w[4], Polynomials& p) {
  for (int c = 0; c < 3; ++c) {
    // Lane b of a[r]: row r of M times blend b. The curve through the line's points in u is
    // a0 F0(u) + a1 F1(u) + a2 G0(u) + a3 G1(u) (lane 0), its derivatives in v lanes 1 and 2.
    Lanes a[4];
    for (int r = 0; r < 4; ++r) {
      const double* mr = m + 16 * c + 4 * r;
      a[r] = mr[0] * w[0] + mr[1] * w[1] + mr[2] * w[2] + mr[3] * w[3];
    }
    // As c0 + c1 u + c2 u^2 + c3 u^3 (docs/kernels.md): c0 is a0, c1 is a2.
    const Lanes c2 = 3 * (a[1] - a[0]) - 2 * a[2] - a[3];
    const Lanes c3 = 2 * (a[0] - a[1]) + a[2] + a[3];
    p.du[0][c] = a[2][0], p.du[1][c] = 2 * c2[0], p.du[2][c] = 3 * c3[0];
    p.duu[0][c] = 2 * c2[0], p.duu[1][c] = 6 * c3[0];
    p.dv[0][c] = a[0][1], p.dv[1][c] = a[2][1], p.dv[2][c] = c2[1], p.dv[3][c] = c3[1];
    p.dvv[0][c] = a[0][2], p.dvv[1][c] = a[2][2], p.dvv[2][c] = c2[2], p.dvv[3][c] = c3[2];
  }
}

// The same for four patch matrices at once, m[0..48) and the three after it (48 numbers apart),
// patch l in lane l: blend b's products are then those of lane b above, with the same operations.
[[gnu::always_inline]] inline void polynomials(const double* m, const Blend& v,
                                               PolynomialsOf<Lanes>& p) {
  const double* const w[3] = {v.f, v.d1, v.d2};
  for (int c = 0; c < 3; ++c) {
    Lanes a[3][4], c2[3], c3[3];
    for (int r = 0; r < 4; ++r) {
      // mk: element k of row r of each patch's M.
      const double* e = m + 16 * c + 4 * r;
      const Lanes m0 = {e[0], e[48], e[96], e[144]}, m1 = {e[1], e[49], e[97], e[145]};
      const Lanes m2 = {e[2], e[50], e[98], e[146]}, m3 = {e[3], e[51], e[99], e[147]};
      for (int b = 0; b < 3; ++b)
        a[b][r] = m0 * w[b][0] + m1 * w[b][1] + m2 * w[b][2] + m3 * w[b][3];
    }
    for (int b = 0; b < 3; ++b) {
      c2[b] = 3 * (a[b][1] - a[b][0]) - 2 * a[b][2] - a[b][3];
      c3[b] = 2 * (a[b][0] - a[b][1]) + a[b][2] + a[b][3];
    }
    p.du[0][c] = a[0][2], p.du[1][c] = 2 * c2[0], p.du[2][c] = 3 * c3[0];
    p.duu[0][c] = 2 * c2[0], p.duu[1][c] = 6 * c3[0];
    p.dv[0][c] = a[1][0], p.dv[1][c] = a[1][2], p.dv[2][c] = c2[1], p.dv[3][c] = c3[1];
    p.dvv[0][c] = a[2][0], p.dvv[1][c] = a[2][2], p.dvv[2][c] = c2[2], p.dvv[3][c] = c3[2];
  }
}

// Pu, Puu, Pv and Pvv (d[0..3], per coordinate) at u = s by Horner's rule: a number, four points
// of a patch in lanes, or one point of four patches, with the same operations.
template <class T, class P, class S>
[[gnu::always_inline]] inline void derivatives(const PolynomialsOf<P>& p, const S& s, T d[4][3]) {
  for (int c = 0; c < 3; ++c) {
    d[0][c] = (p.du[2][c] * s + p.du[1][c]) * s + p.du[0][c];
    d[1][c] = p.duu[1][c] * s + p.duu[0][c];
    d[2][c] = ((p.dv[3][c] * s + p.dv[2][c]) * s + p.dv[1][c]) * s + p.dv[0][c];
    d[3][c] = ((p.dvv[3][c] * s + p.dvv[2][c]) * s + p.dvv[1][c]) * s + p.dvv[0][c];
  }
}

// What becomes of the curvature vectors of the points, four at a time (`lanes`: lane l is point
// m + l apart) or one at a time (`one`): kept, six numbers a point ...
struct Keep {
  double* out;
  [[gnu::always_inline]] inline void lanes(std::size_t m, std::size_t apart, const Vec3Lanes& along,
                                           const Vec3Lanes& across) {
    for (int l = 0; l < 4; ++l) {
      double* o = out + 6 * (m + l * apart);
      o[0] = along.x[l], o[1] = along.y[l], o[2] = along.z[l];
      o[3] = across.x[l], o[4] = across.y[l], o[5] = across.z[l];
    }
  }
  void one(std::size_t m, Vec3 along, Vec3 across) {
    along.store(out + 6 * m);
    across.store(out + 6 * m + 3);
  }
};

// ... or measured and, for a parallel projection, projected (CurvatureRows::combs) ...
template <bool project>
struct Measure {
  const ProjectiveMap* map;
  double* images;
  LargestCurvature& largest;
  Lanes squared = {0, 0, 0, 0};  // the largest finite squares, lane by lane
  [[gnu::always_inline]] inline void take(const Vec3Lanes& k) {
    const Lanes k2 = k.x * k.x + k.y * k.y + k.z * k.z;  // dot()'s order
    const LaneMask finite = k2 < std::numeric_limits<double>::infinity();
    if (finite[0] & finite[1] & finite[2] & finite[3]) {
      squared = k2 > squared ? k2 : squared;
      return;
    }
    for (int l = 0; l < 4; ++l) largest.add({k.x[l], k.y[l], k.z[l]});
  }
  [[gnu::always_inline]] inline void lanes(std::size_t m, std::size_t apart, const Vec3Lanes& along,
                                           const Vec3Lanes& across) {
    take(along);
    take(across);
    if constexpr (project) {
      Lanes xy[4];
      linear_image(map->m, along.x, along.y, along.z, xy[0], xy[1]);
      linear_image(map->m, across.x, across.y, across.z, xy[2], xy[3]);
      for (int l = 0; l < 4; ++l)
        for (int c = 0; c < 4; ++c) images[4 * (m + l * apart) + c] = xy[c][l];
    }
  }
  void one(std::size_t m, Vec3 along, Vec3 across) {
    if constexpr (project)
      comb_vectors(along, across, map, images + 4 * m, largest);
    else
      comb_vectors(along, across, nullptr, nullptr, largest);
  }
  void finish() {
    largest.squared = std::max({largest.squared, squared[0], squared[1], squared[2], squared[3]});
  }
};

// ... or the images seen from an eye of the points' combs' ends p - s k (CurvatureRows::
// conic_combs), four numbers a point, with what the images find, the vectors measured.
struct ConicCombs {
  const double* points;  // the points, three numbers each
  double scale;
  double* out;
  ConicImages conic;
  Measure<false> measure;
  Lanes seen = {0, 0, 0, 0};  // x * 0 of the images, summed
  [[gnu::always_inline]] inline void lanes(std::size_t m, std::size_t apart, const Vec3Lanes& along,
                                           const Vec3Lanes& across) {
    measure.lanes(m, apart, along, across);
    const Vec3Lanes p = load_lanes(points + 3 * m, 3 * apart);
    Lanes x[2], y[2];
    conic(p.x - scale * along.x, p.y - scale * along.y, p.z - scale * along.z, x[0], y[0]);
    conic(p.x - scale * across.x, p.y - scale * across.y, p.z - scale * across.z, x[1], y[1]);
    for (int l = 0; l < 4; ++l) {
      double* o = out + 4 * (m + l * apart);
      o[0] = x[0][l], o[1] = y[0][l], o[2] = x[1][l], o[3] = y[1][l];
    }
    seen += (x[0] * 0.0 + y[0] * 0.0) + (x[1] * 0.0 + y[1] * 0.0);
  }
  void one(std::size_t m, Vec3 along, Vec3 across) {
    measure.one(m, along, across);
    const Vec3 p = Vec3::load(points + 3 * m);
    const Point2 a = conic(p - scale * along), b = conic(p - scale * across);
    a.store(out + 4 * m);
    b.store(out + 4 * m + 2);
    seen[0] += (a.x * 0.0 + a.y * 0.0) + (b.x * 0.0 + b.y * 0.0);
  }
};

// The curvature vectors of the points at u[0..n) of a patch, points `first` onwards of `sink`
// (u runs along the curves, v along the stringers). Four points at a time, then one at a time.
template <class Sink>
[[gnu::always_inline]] inline void patch_curvature(const Polynomials& p, const double* u,
                                                   std::size_t n, Sink& sink, std::size_t first) {
  std::size_t m = 0;
  for (; m + 4 <= n; m += 4) {
    Lanes d[4][3];
    derivatives(p, Lanes{u[m], u[m + 1], u[m + 2], u[m + 3]}, d);
    Vec3Lanes along, across;
    curvatures(d, along, across);
    sink.lanes(first + m, 1, along, across);
  }
  for (; m < n; ++m) {
    double d[4][3];
    derivatives(p, u[m], d);
    sink.one(first + m, curvature_vector(Vec3::load(d[0]), Vec3::load(d[1])),
             curvature_vector(Vec3::load(d[2]), Vec3::load(d[3])));
  }
}

// One grid line at v (blends `v`) across a row of `count` patch matrices: `step` points a patch,
// one more (u = 1) in the last, at u[0..step].
struct RowJob {
  const double* patch_row;
  std::size_t count, step;
  const double* u;
};
template <class Sink>
[[gnu::always_inline]] inline void curvature_row_body(const RowJob& job, const Blend& v, Sink& sink,
                                                      std::size_t first) {
  std::size_t j = 0;
  // Four patches at a time (the last has a point more: not among them), patch j + l in lane l,
  // their points at u one after the other.
  for (; j + 4 < job.count; j += 4) {
    PolynomialsOf<Lanes> p;
    polynomials(job.patch_row + 48 * j, v, p);
    for (std::size_t m = 0; m < job.step; ++m) {
      Lanes d[4][3];
      derivatives(p, job.u[m], d);
      Vec3Lanes along, across;
      curvatures(d, along, across);
      sink.lanes(first + job.step * j + m, job.step, along, across);
    }
  }
  // The others a patch at a time: the blends in lanes, then four points at a time.
  Lanes w[4];
  for (int k = 0; k < 4; ++k) w[k] = Lanes{v.f[k], v.d1[k], v.d2[k], 0};
  for (; j < job.count; ++j) {
    Polynomials p;
    polynomials(job.patch_row + 48 * j, w, p);
    const std::size_t n = j + 1 < job.count ? job.step : job.step + 1;
    patch_curvature(p, job.u, n, sink, first + job.step * j);
  }
}

template <class Sink>
void curvature_row_base(const RowJob& job, const Blend& v, Sink& sink, std::size_t first) {
  curvature_row_body(job, v, sink, first);
}

#if IGDS_X86
template <class Sink>
__attribute__((target("avx2"))) void curvature_row_avx2(const RowJob& job, const Blend& v,
                                                        Sink& sink, std::size_t first) {
  curvature_row_body(job, v, sink, first);
}
#endif

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
      made_(source ? 48 * patches_in_row_ : 0) {
  if (!source)
    require_shape("PATCHES", &patches,
                  {std::size_t(in.nocur) - 1, std::size_t(in.nostr) - 1, 3, 4, 4});
  for (std::size_t k = 0; k <= step_; ++k) column_u_[k] = double(k) / double(step_);
}

template <class Sink>
void CurvatureRows::each_row(std::size_t first, std::size_t last, Sink& sink) {
  const std::size_t pc = patches_in_row_;
  auto row_curvature = curvature_row_base<Sink>;
#if IGDS_X86
  if (best_kernels()) row_curvature = curvature_row_avx2<Sink>;
#endif
  for (std::size_t i = first; i < last; ++i) {
    const Place row = place(i, std::size_t(in_.nocur), std::size_t(in_.intcu));
    if (source_ && made_row_ != row.patch) {
      (void)coons_patch_row(*source_, row.patch, made_.data());  // finite: the surface was made
      made_row_ = row.patch;
    }
    const double* patch_row = source_ ? made_.data() : patches_.data() + 48 * row.patch * pc;
    row_curvature({patch_row, pc, step_, column_u_.data()}, blend(row.s), sink,
                  cols_ * (i - first));
  }
}

void CurvatureRows::operator()(std::size_t first, std::size_t last, double* out) {
  Keep keep{out};
  each_row(first, last, keep);
}

ProjectedPart CurvatureRows::conic_combs(std::size_t first, std::size_t last, const double* points,
                                         double scale, const ConicFrame& frame, Vec3 eye,
                                         double* images, LargestCurvature& largest) {
  ConicCombs combs{points, scale, images, ConicImages(frame, eye), {nullptr, nullptr, largest}};
  each_row(first, last, combs);
  combs.conic.finish();
  combs.measure.finish();
  const std::size_t n = 2 * (last - first) * cols_;
  ProjectedPart found{n, combs.conic.behind, combs.conic.about_eye};
  const Lanes& seen = combs.seen;
  if (seen[0] + seen[1] + seen[2] + seen[3] != 0)
    found.not_finite = first_not_finite(images, 2 * n) / 2;
  return found;
}

void comb_ends(Vec3 p, Vec3 along, Vec3 across, double scale, double* out) {
  (p - scale * along).store(out);
  (p - scale * across).store(out + 3);
}

void CurvatureRows::combs(std::size_t first, std::size_t last, LargestCurvature& largest,
                          const ProjectiveMap* map, double* images) {
  if (map) {
    Measure<true> measure{map, images, largest};
    each_row(first, last, measure);
    measure.finish();
  } else {
    Measure<false> measure{nullptr, nullptr, largest};
    each_row(first, last, measure);
    measure.finish();
  }
}

void LargestCurvature::add(Vec3 k) {
  const double k2 = dot(k, k);
  if (k2 <= squared) return;
  if (std::isfinite(k2))
    squared = k2;
  else if (const double length = norm(k); std::isfinite(length))
    overflowing = std::max(overflowing, length);
}

void LargestCurvature::add(const LargestCurvature& other) {
  squared = std::max(squared, other.squared);
  overflowing = std::max(overflowing, other.overflowing);
}

double LargestCurvature::length() const {
  return std::max(std::sqrt(squared), overflowing);
}

std::size_t comb_images(const double* points, double* combs, std::size_t n, double scale) {
  // A block at a time, x * 0 summed as in first_not_finite; a block whose sum is not 0 is searched.
  constexpr std::size_t block = 1024;
  for (std::size_t from = 0; from < n; from += block) {
    const std::size_t to = std::min(n, from + block);
    Lanes seen = {0, 0, 0, 0};
    for (std::size_t k = from; k < to; ++k) {
      const double x = points[2 * k], y = points[2 * k + 1];
      Lanes comb;
      std::memcpy(&comb, combs + 4 * k, sizeof comb);
      comb = Lanes{x, y, x, y} - scale * comb;
      std::memcpy(combs + 4 * k, &comb, sizeof comb);
      seen += comb * 0.0;
    }
    if (seen[0] + seen[1] + seen[2] + seen[3] == 0) continue;
    const std::size_t bad = first_not_finite(combs + 4 * from, 4 * (to - from));
    if (bad < 4 * (to - from)) return (4 * from + bad) / 2;
  }
  return 2 * n;
}

void comb_vectors(Vec3 along, Vec3 across, const ProjectiveMap* map, double* images,
                  LargestCurvature& largest) {
  largest.add(along);
  largest.add(across);
  if (!map) return;
  linear_image(map->m, along.x, along.y, along.z, images[0], images[1]);
  linear_image(map->m, across.x, across.y, across.z, images[2], images[3]);
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

#include "workspace/kernels/fit.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <vector>

#include "workspace/kernels/coons.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/processor.h"
#include "workspace/kernels/project.h"
#include "workspace/kernels/spline.h"

// On x86-64 the hot loops also exist compiled for AVX2 with FMA, chosen at run time (processor.h),
// and very large grids are written with streaming stores.
#if IGDS_X86
#include <immintrin.h>
#endif

namespace igds {

GridShape intpn_shape(int nocur, int nostr, int intcu, int intst) {
  const std::size_t nc = nocur, ns = nostr, ic = intcu, is = intst;
  return {nc + ic * (nc - 1), ns + is * (ns - 1)};
}

namespace {

// The blending weights of the int+2 parameter values a/(int+1), a = 0..int+1, as an
// (int+2) x 4 matrix W (docs/kernels.md); the parameters are computed as a/(int+1), never
// accumulated.
std::vector<double> weights(int inserted) {
  const int n = inserted + 2;
  std::vector<double> w(4 * std::size_t(n));
  for (int a = 0; a < n; ++a) {
    Hermite h = hermite(double(a) / double(inserted + 1));
    w[4 * a + 0] = h.f0;
    w[4 * a + 1] = h.f1;
    w[4 * a + 2] = h.g0;
    w[4 * a + 3] = h.g1;
  }
  return w;
}

// Output columns handled at a time: the four curve polynomials of a chunk stay in the L2 cache.
constexpr std::size_t chunk = 2048;

// Outputs of at least this many doubles (32 MB) are written with streaming stores.
constexpr std::size_t streaming = std::size_t(1) << 22;

struct FitJob;
using CurvePolynomials = void (*)(const FitJob&, const double*, std::size_t, std::size_t, double*,
                                  double*, double*, double*);
using Combine = bool (*)(const double*, std::size_t, const double*, const double*, const double*,
                         const double*, const double*, double*);

struct FitJob {
  std::size_t nc, ns, ic, is, rows, cols;
  const double* patches;      // PATCHES, or null: each row made from `source` when needed
  const PatchSource* source;  // when `patches` is null
  std::atomic<std::size_t>* patch_not_finite;  // the least index found in the rows made
  const double* wv;                            // (ic+2) x 4
  const double* wu;                            // (is+2) x 4
  double centre[3];
  double* intpn;
  CurvePolynomials polynomials;
  Combine combine;
  Vec3View points;  // the input points, written over their places in INTPN
};

// The four curve polynomials of a patch row (`row`: its matrices) over output columns [j0, j1):
// q[c] holds, point by point (x y z), W_u M[.][c] with M's corners relative to the local origin.
// Row b of the patch row is then sum_c W_v[b][c] q[c]: a 4-term combination of contiguous memory.
template <class = void>
[[gnu::always_inline]] inline void curve_polynomials_body(
    const FitJob& job, const double* row, std::size_t j0, std::size_t j1, double* __restrict q0,
    double* __restrict q1, double* __restrict q2, double* __restrict q3) {
  // One vector holds a row of M (its 4 columns c), so each output column costs 12 FMAs.
  typedef double v4 __attribute__((vector_size(32)));
  for (std::size_t col = j0; col < j1;) {
    const std::size_t j = std::min(col / (job.is + 1), job.ns - 2);
    const std::size_t first = col - j * (job.is + 1);
    const std::size_t count = j + 2 == job.ns ? job.is + 2 : job.is + 1;
    const std::size_t last = std::min(count, first + (j1 - col));
    const double* src = row + j * 48;
    v4 m[3][4];
    for (int k = 0; k < 3; ++k) {
      for (int r = 0; r < 4; ++r) std::memcpy(&m[k][r], src + 16 * k + 4 * r, sizeof(v4));
      // Corners relative to the local origin: large offsets cost no precision (docs/kernels.md).
      const v4 shift = {job.centre[k], job.centre[k], 0, 0};
      m[k][0] -= shift;
      m[k][1] -= shift;
    }
    const std::size_t o = 3 * (col - j0);
    double *o0 = q0 + o, *o1 = q1 + o, *o2 = q2 + o, *o3 = q3 + o;
    for (std::size_t a = first; a < last; ++a, o0 += 3, o1 += 3, o2 += 3, o3 += 3) {
      const double* fu = job.wu + 4 * a;
      for (int k = 0; k < 3; ++k) {
        const v4 s = fu[0] * m[k][0] + fu[1] * m[k][1] + fu[2] * m[k][2] + fu[3] * m[k][3];
        o0[k] = s[0];
        o1[k] = s[1];
        o2[k] = s[2];
        o3[k] = s[3];
      }
    }
    col += last - first;
  }
}

// One stretch of an output row: out = origin + fv . q, a 4-term FMA over contiguous memory. True
// when every number written is finite: x * 0 is 0 for a finite x and NaN for the rest, summed in
// the registers as the numbers are made (the check of docs/kernels.md, "Data checks").
template <class = void>
[[gnu::always_inline]] inline bool combine_body(
    const double* fv, std::size_t n, const double* __restrict origin, const double* __restrict q0,
    const double* __restrict q1, const double* __restrict q2, const double* __restrict q3,
    double* __restrict out) {
  typedef double v4 __attribute__((vector_size(32)));
  const double w0 = fv[0], w1 = fv[1], w2 = fv[2], w3 = fv[3];
  v4 seen = {0, 0, 0, 0};
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    v4 o, a0, a1, a2, a3;
    std::memcpy(&o, origin + k, sizeof o);
    std::memcpy(&a0, q0 + k, sizeof a0);
    std::memcpy(&a1, q1 + k, sizeof a1);
    std::memcpy(&a2, q2 + k, sizeof a2);
    std::memcpy(&a3, q3 + k, sizeof a3);
    const v4 v = o + (w0 * a0 + w1 * a1 + w2 * a2 + w3 * a3);
    std::memcpy(out + k, &v, sizeof v);
    seen += v * 0.0;
  }
  double rest = 0;
  for (; k < n; ++k) {
    out[k] = origin[k] + (w0 * q0[k] + w1 * q1[k] + w2 * q2[k] + w3 * q3[k]);
    rest += out[k] * 0.0;
  }
  return seen[0] + seen[1] + seen[2] + seen[3] + rest == 0;
}

void curve_polynomials_base(const FitJob& job, const double* row, std::size_t j0, std::size_t j1,
                            double* q0, double* q1, double* q2, double* q3) {
  curve_polynomials_body(job, row, j0, j1, q0, q1, q2, q3);
}

bool combine_base(const double* fv, std::size_t n, const double* origin, const double* q0,
                  const double* q1, const double* q2, const double* q3, double* out) {
  return combine_body(fv, n, origin, q0, q1, q2, q3, out);
}

#if IGDS_X86
__attribute__((target("avx2,fma"))) void curve_polynomials_avx2(const FitJob& job,
                                                                const double* row, std::size_t j0,
                                                                std::size_t j1, double* q0,
                                                                double* q1, double* q2,
                                                                double* q3) {
  curve_polynomials_body(job, row, j0, j1, q0, q1, q2, q3);
}

__attribute__((target("avx2,fma"))) bool combine_avx2(const double* fv, std::size_t n,
                                                      const double* origin, const double* q0,
                                                      const double* q1, const double* q2,
                                                      const double* q3, double* out) {
  return combine_body(fv, n, origin, q0, q1, q2, q3, out);
}

// The same with streaming stores, for grids much larger than the caches: the output goes to
// memory without first being read into the cache, which halves the memory traffic.
bool combine_stream_sse2(const double* fv, std::size_t n, const double* __restrict origin,
                         const double* __restrict q0, const double* __restrict q1,
                         const double* __restrict q2, const double* __restrict q3,
                         double* __restrict out) {
  std::size_t k = 0;
  bool finite = true;
  if (reinterpret_cast<std::uintptr_t>(out) % 16 != 0 && n > 0) {
    finite = combine_base(fv, 1, origin, q0, q1, q2, q3, out);
    k = 1;
  }
  const __m128d zero = _mm_setzero_pd();
  __m128d seen = zero;
  const __m128d w0 = _mm_set1_pd(fv[0]), w1 = _mm_set1_pd(fv[1]), w2 = _mm_set1_pd(fv[2]),
                w3 = _mm_set1_pd(fv[3]);
  for (; k + 2 <= n; k += 2) {
    __m128d v = _mm_mul_pd(w0, _mm_loadu_pd(q0 + k));
    v = _mm_add_pd(v, _mm_mul_pd(w1, _mm_loadu_pd(q1 + k)));
    v = _mm_add_pd(v, _mm_mul_pd(w2, _mm_loadu_pd(q2 + k)));
    v = _mm_add_pd(v, _mm_mul_pd(w3, _mm_loadu_pd(q3 + k)));
    v = _mm_add_pd(_mm_loadu_pd(origin + k), v);
    _mm_stream_pd(out + k, v);
    seen = _mm_add_pd(seen, _mm_mul_pd(v, zero));
  }
  double lanes[2];
  _mm_storeu_pd(lanes, seen);
  return combine_base(fv, n - k, origin + k, q0 + k, q1 + k, q2 + k, q3 + k, out + k) && finite &&
         lanes[0] + lanes[1] == 0;
}

__attribute__((target("avx2,fma"))) bool combine_stream_avx2(
    const double* fv, std::size_t n, const double* __restrict origin, const double* __restrict q0,
    const double* __restrict q1, const double* __restrict q2, const double* __restrict q3,
    double* __restrict out) {
  std::size_t k = 0;
  bool finite = true;
  const std::size_t head = (32 - reinterpret_cast<std::uintptr_t>(out) % 32) % 32 / 8;
  if (head > 0) {
    k = std::min(head, n);
    finite = combine_body(fv, k, origin, q0, q1, q2, q3, out);
  }
  const __m256d zero = _mm256_setzero_pd();
  __m256d seen = zero;
  const __m256d w0 = _mm256_set1_pd(fv[0]), w1 = _mm256_set1_pd(fv[1]), w2 = _mm256_set1_pd(fv[2]),
                w3 = _mm256_set1_pd(fv[3]);
  for (; k + 4 <= n; k += 4) {
    __m256d v = _mm256_mul_pd(w0, _mm256_loadu_pd(q0 + k));
    v = _mm256_fmadd_pd(w1, _mm256_loadu_pd(q1 + k), v);
    v = _mm256_fmadd_pd(w2, _mm256_loadu_pd(q2 + k), v);
    v = _mm256_fmadd_pd(w3, _mm256_loadu_pd(q3 + k), v);
    v = _mm256_add_pd(_mm256_loadu_pd(origin + k), v);
    _mm256_stream_pd(out + k, v);
    seen = _mm256_add_pd(seen, _mm256_mul_pd(v, zero));
  }
  double lanes[4];
  _mm256_storeu_pd(lanes, seen);
  return combine_body(fv, n - k, origin + k, q0 + k, q1 + k, q2 + k, q3 + k, out + k) && finite &&
         lanes[0] + lanes[1] + lanes[2] + lanes[3] == 0;
}
#endif

// AVX2 with FMA when the processor has it (and the best code is wanted); streaming stores for
// outputs far larger than the caches, ordinary stores otherwise so that a small grid stays in the
// cache for its display.
void choose_kernels(FitJob& job, std::size_t doubles) {
  job.polynomials = curve_polynomials_base;
  job.combine = combine_base;
#if IGDS_X86
  const bool avx2 = best_kernels();
  if (avx2) {
    job.polynomials = curve_polynomials_avx2;
    job.combine = combine_avx2;
  }
  if (doubles >= streaming) job.combine = avx2 ? combine_stream_avx2 : combine_stream_sse2;
#else
  (void)doubles;
#endif
}

// Output rows [first, last): for each patch row (made first when PATCHES are not kept) and chunk
// of columns, the curve polynomials once, then every output row of that patch row in the chunk.
// Returns the index in INTPN of the first stretch written that holds a number not finite, or the
// size of INTPN.
std::size_t fit_rows(const FitJob& job, std::size_t first, std::size_t last) {
  std::size_t not_finite = job.rows * job.cols * 3;
  const std::size_t width = std::min(chunk, job.cols);
  const std::size_t row_size = (job.ns - 1) * 48;
  std::vector<double> buffer(5 * 3 * width), made(job.patches ? 0 : row_size);
  double* q[4] = {buffer.data(), buffer.data() + 3 * width, buffer.data() + 6 * width,
                  buffer.data() + 9 * width};
  double* origin = buffer.data() + 12 * width;
  for (std::size_t k = 0; k < 3 * width; ++k) origin[k] = job.centre[k % 3];
  for (std::size_t row = first; row < last;) {
    const std::size_t i = std::min(row / (job.ic + 1), job.nc - 2);
    const std::size_t end = std::min(last, i + 2 == job.nc ? job.rows : (i + 1) * (job.ic + 1));
    const double* patch_row = job.patches ? job.patches + i * row_size : made.data();
    if (!job.patches) {
      const std::size_t k = coons_patch_row(*job.source, i, made.data());
      if (k < row_size) keep_least(*job.patch_not_finite, i * row_size + k);
    }
    for (std::size_t j0 = 0; j0 < job.cols; j0 += width) {
      const std::size_t j1 = std::min(job.cols, j0 + width);
      job.polynomials(job, patch_row, j0, j1, q[0], q[1], q[2], q[3]);
      for (std::size_t r = row; r < end; ++r) {
        if (!job.combine(job.wv + 4 * (r - i * (job.ic + 1)), 3 * (j1 - j0), origin, q[0], q[1],
                         q[2], q[3], job.intpn + 3 * (r * job.cols + j0)))
          not_finite = std::min(not_finite, 3 * (r * job.cols + j0));
        // An input curve's row: its input points come out bit-exact (docs/kernels.md), written
        // over the ones computed while the row is at hand.
        if (r % (job.ic + 1) != 0) continue;
        const std::size_t curve = r / (job.ic + 1);
        for (std::size_t j = (j0 + job.is) / (job.is + 1) * (job.is + 1); j < j1; j += job.is + 1) {
          const Vec3 p = job.points[curve * job.ns + j / (job.is + 1)];
          double* to = job.intpn + 3 * (r * job.cols + j);
          to[0] = p.x, to[1] = p.y, to[2] = p.z;
        }
      }
    }
    row = end;
  }
#if IGDS_X86
  // Streaming stores are weakly ordered: make them visible before the thread reports done.
  _mm_sfence();
#endif
  return not_finite;
}

// FIT from stored patches (`patches`) or from rows made as they are needed (`source`).
std::size_t fit_grid(int intcu, int intst, const double* patches, const PatchSource& source,
                     std::atomic<std::size_t>* patch_not_finite, Array& intpn) {
  const int nocur = int(source.nocur), nostr = int(source.nostr);
  const GridShape shape = intpn_shape(nocur, nostr, intcu, intst);
  const unsigned threads = threads_for(shape.rows * shape.cols * 3);
  intpn.reshape_for_output({shape.rows, shape.cols, 3});
  const std::vector<double> wv = weights(intcu), wu = weights(intst);
  const Vec3 c = bounding_box_centre(source.points);
  FitJob job{source.nocur,
             source.nostr,
             std::size_t(intcu),
             std::size_t(intst),
             shape.rows,
             shape.cols,
             patches,
             &source,
             patch_not_finite,
             wv.data(),
             wu.data(),
             {c.x, c.y, c.z},
             intpn.data(),
             nullptr,
             nullptr,
             source.points};
  choose_kernels(job, intpn.size());
  std::atomic<std::size_t> not_finite{intpn.size()};
  parallel_for(shape.rows, threads, [&](std::size_t first, std::size_t last) {
    keep_least(not_finite, fit_rows(job, first, last));
  });
  // Every number before the first stretch found not finite is (the input points are finite): the
  // first one is looked for from there, in the grid as it is now.
  const std::size_t from = not_finite.load();
  if (from == intpn.size()) return from;
  return from + first_not_finite(intpn.data() + from, intpn.size() - from);
}

}  // namespace

std::size_t fit(int nocur, int nostr, int intcu, int intst, const Array& patches, Vec3View points,
                Array& intpn) {
  const PatchSource source{std::size_t(nocur), std::size_t(nostr), points, nullptr, {}};
  return fit_grid(intcu, intst, patches.data(), source, nullptr, intpn);
}

FitResult fit(int intcu, int intst, const PatchSource& source, Array& intpn) {
  std::atomic<std::size_t> patch_not_finite{(source.nocur - 1) * (source.nostr - 1) * 48};
  const std::size_t k = fit_grid(intcu, intst, nullptr, source, &patch_not_finite, intpn);
  return {patch_not_finite.load(), k};
}

}  // namespace igds

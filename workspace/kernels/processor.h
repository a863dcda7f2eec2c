// Which compiled form of the kernels' hot loops runs (docs/kernels.md, "Processors"): on x86-64
// the loops of FIT and of the curvature also exist compiled for AVX2, chosen at run time.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__)
#define IGDS_X86 1
#else
#define IGDS_X86 0
#endif

#include <cstddef>

namespace igds {

// Four numbers computed at once (GCC's vector extension: one AVX instruction, or two SSE2 ones),
// and the mask of a comparison of two such (all bits set where it holds). A vector is passed by
// reference: by value it would change the calling convention with the processor's instructions.
using Lanes = double __attribute__((vector_size(32)));
using LaneMask = long long __attribute__((vector_size(32)));

// Three coordinates of four points, a lane each.
struct Vec3Lanes {
  Lanes x, y, z;
};
// The four points `stride` doubles apart from p.
[[gnu::always_inline]] inline Vec3Lanes load_lanes(const double* p, std::size_t s) {
  return {Lanes{p[0], p[s], p[2 * s], p[3 * s]}, Lanes{p[1], p[s + 1], p[2 * s + 1], p[3 * s + 1]},
          Lanes{p[2], p[s + 2], p[2 * s + 2], p[3 * s + 2]}};
}

// std::min(lo, v) and std::max(hi, v) of each lane (one MINPD or MAXPD: the same choice, lo or hi
// kept when a lane is NaN or both are zeros).
[[gnu::always_inline]] inline void lower(Lanes& lo, const Lanes& v) {
  lo = v < lo ? v : lo;
}
[[gnu::always_inline]] inline void raise(Lanes& hi, const Lanes& v) {
  hi = hi < v ? v : hi;
}

// The best form the processor allows (the default), or the baseline one everywhere (so that
// tests exercise both on a machine that has AVX2).
enum class KernelCode { best, baseline };
void use_kernel_code(KernelCode code);

// True when the AVX2 forms run: the processor has AVX2 and FMA and the best form is wanted.
bool best_kernels();

// The form in use, in words (for igds --version).
const char* kernel_code_in_use();

}  // namespace igds

// Which compiled form of the kernels' hot loops runs (docs/kernels.md, "Processors"): on x86-64
// the loops of FIT and of the curvature also exist compiled for AVX2, chosen at run time.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__)
#define IGDS_X86 1
#else
#define IGDS_X86 0
#endif

namespace igds {

// Four numbers computed at once (GCC's vector extension: one AVX instruction, or two SSE2 ones),
// and the mask of a comparison of two such (all bits set where it holds). A vector is passed by
// reference: by value it would change the calling convention with the processor's instructions.
using Lanes = double __attribute__((vector_size(32)));
using LaneMask = long long __attribute__((vector_size(32)));

// The best form the processor allows (the default), or the baseline one everywhere (so that
// tests exercise both on a machine that has AVX2).
enum class KernelCode { best, baseline };
void use_kernel_code(KernelCode code);

// True when the AVX2 forms run: the processor has AVX2 and FMA and the best form is wanted.
bool best_kernels();

// The form in use, in words (for igds --version).
const char* kernel_code_in_use();

}  // namespace igds

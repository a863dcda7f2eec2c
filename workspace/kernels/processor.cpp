#include "workspace/kernels/processor.h"

#include <atomic>

namespace igds {

namespace {

std::atomic<KernelCode> kernel_code{KernelCode::best};

bool has_avx2_fma() {
#if IGDS_X86
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
#else
  return false;
#endif
}

}  // namespace

void use_kernel_code(KernelCode code) {
  kernel_code.store(code);
}

bool best_kernels() {
  return kernel_code.load() == KernelCode::best && has_avx2_fma();
}

const char* kernel_code_in_use() {
  if (best_kernels()) return "AVX2 and FMA";
  return IGDS_X86 ? "SSE2" : "portable";
}

}  // namespace igds

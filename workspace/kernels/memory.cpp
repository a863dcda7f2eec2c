#include "workspace/kernels/memory.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace igds {

void advise_huge_pages(const void* p, std::size_t bytes) {
  if (bytes < huge_page_advice_bytes) return;
  static const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const auto begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (begin + page - 1) / page * page;
  const std::uintptr_t last = (begin + bytes) / page * page;
  // A kernel without transparent huge pages refuses the advice: the block is used as it is.
  if (last > first) (void)::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

}  // namespace igds

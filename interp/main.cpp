// igds: Interactive Design of Interpolated Surfaces.
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <new>
#include <string>
#include <string_view>

#include "interp/start.h"
#include "workspace/kernels/big_blocks.h"
#include "workspace/kernels/interrupt.h"

namespace {

// glibc asks for transparent huge pages for its heap only when told so before the program
// starts, by the tunable glibc.malloc.hugetlb=1 in GLIBC_TUNABLES: igds starts itself again once,
// with the same arguments and the tunable added (docs/decisions.md, "Memory kept"). A user's own
// glibc.malloc.hugetlb is left as it is, and without /proc igds goes on as it was started.
void start_again_with_huge_pages([[maybe_unused]] char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
  constexpr std::string_view tunable = "glibc.malloc.hugetlb";
  const char* given = std::getenv("GLIBC_TUNABLES");
  const std::string before = given ? given : "";
  if (before.find(tunable) != std::string::npos) return;
  const std::string with = (before.empty() ? "" : before + ":") + std::string(tunable) + "=1";
  if (::setenv("GLIBC_TUNABLES", with.c_str(), 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  if (given)
    ::setenv("GLIBC_TUNABLES", before.c_str(), 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
#endif
}

}  // namespace

// Large blocks (an image, INTPN, a plot's points) come from the kept memory of the blocks freed
// before, whatever their sizes: the heap would leave them as holes a larger block does not fit,
// and grow (docs/decisions.md, "Memory kept"). Under a sanitizer (IGDS_SANITIZED, set by
// CMakeLists.txt), which watches every block, everything comes from the heap.
#ifndef IGDS_SANITIZED
void* operator new(std::size_t bytes) {
  if (bytes >= igds::big_blocks::smallest)
    if (void* p = igds::big_blocks::allocate(bytes)) return p;
  for (;;) {
    if (void* p = std::malloc(bytes == 0 ? 1 : bytes)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

void operator delete(void* p) noexcept {
  if (igds::big_blocks::owns(p))
    igds::big_blocks::release(p);
  else
    std::free(p);
}

void operator delete(void* p, std::size_t) noexcept {
  operator delete(p);
}

// The same for blocks that must begin on a boundary (a file's buffers, for writes straight to the
// disk): the large blocks begin on 2 MB.
void* operator new(std::size_t bytes, std::align_val_t align) {
  const auto boundary = std::max(static_cast<std::size_t>(align), sizeof(void*));
  if (bytes >= igds::big_blocks::smallest && boundary <= igds::big_blocks::boundary)
    if (void* p = igds::big_blocks::allocate(bytes)) return p;
  const std::size_t rounded = (std::max<std::size_t>(bytes, 1) + boundary - 1) & ~(boundary - 1);
  for (;;) {
    if (void* p = std::aligned_alloc(boundary, rounded)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

void operator delete(void* p, std::align_val_t) noexcept {
  operator delete(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  operator delete(p);
}
#endif

int main(int argc, char** argv) {
  // Before any thread exists: no thread of igds may be ended by Ctrl-C
  // (workspace/kernels/interrupt.h).
  igds::block_interrupts();
  start_again_with_huge_pages(argv);
  // Memory a command frees stays in igds for the next command instead of going back to the
  // system: a DISPLAY, PLOT or EXPORT of 4 M points uses hundreds of megabytes of scratch, and
  // every fresh page costs a fault and its clearing (docs/decisions.md, "Memory kept"). The large
  // blocks keep theirs (above); the heap, where the smaller blocks come from, keeps its own.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest: blocks below it come from the heap
  mallopt(M_MMAP_MAX, 0);               // and the larger ones too (under a sanitizer)
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  // Every thread allocates from that one heap, in huge pages: glibc would give each new thread a
  // heap of its own, in small pages, so that a command's second thread faulted its memory in
  // 4 KB at a time, and the memory one thread freed was not there for another's next command.
  mallopt(M_ARENA_MAX, 1);
  return igds::igds_main(argc, argv);
}

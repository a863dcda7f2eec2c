// igds: Interactive Design of Interpolated Surfaces.
#include <malloc.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <string_view>

#include "interp/start.h"

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

int main(int argc, char** argv) {
  start_again_with_huge_pages(argv);
  // Memory a command frees stays in igds for the next command instead of going back to the
  // system: a DISPLAY, PLOT or EXPORT of 4 M points uses hundreds of megabytes of scratch, and
  // every fresh page costs a fault and its clearing (docs/decisions.md, "Memory kept").
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest: blocks below it come from the heap
  mallopt(M_MMAP_MAX, 0);               // and the larger ones too (an image of 64 MB, INTPN)
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  // Every thread allocates from that one heap, in huge pages: glibc would give each new thread a
  // heap of its own, in small pages, so that a command's second thread faulted its memory in
  // 4 KB at a time, and the memory one thread freed was not there for another's next command.
  mallopt(M_ARENA_MAX, 1);
  return igds::igds_main(argc, argv);
}

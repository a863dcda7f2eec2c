// The huge-page advice of large blocks (memory.h), read back from the kernel's own account of the
// process's mappings: /proc/self/smaps says `hg` in the VmFlags of a mapping so advised.
#include "workspace/kernels/memory.h"

#include <doctest/doctest.h>
#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "workspace/kernels/array.h"
#include "workspace/kernels/coons.h"

using namespace igds;

namespace {

// The VmFlags of the mapping that holds address `p` ("" when none does).
std::string flags_at(const void* p) {
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' '))
      inside = begin <= at && at < end;
    else if (inside && line.rfind("VmFlags:", 0) == 0)
      return line;
  }
  return {};
}

bool advised(const void* p) {
  return flags_at(p).find(" hg") != std::string::npos;
}

// A kernel built without transparent huge pages refuses the advice.
bool kernel_has_huge_pages() {
  return std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled");
}

}  // namespace

TEST_CASE("a block of at least huge_page_advice_bytes is advised to huge pages, a smaller not") {
  const std::size_t size = 4 * huge_page_advice_bytes;
  void* const block =
      ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  REQUIRE(block != MAP_FAILED);
  auto* const bytes = static_cast<char*>(block);
  REQUIRE_FALSE(flags_at(bytes).empty());
  advise_huge_pages(bytes, huge_page_advice_bytes - 4096);
  CHECK_FALSE(advised(bytes));
  // Its whole pages only: from the first page boundary after an unaligned start.
  advise_huge_pages(bytes + 100, 2 * huge_page_advice_bytes);
  CHECK(advised(bytes + 4096) == kernel_has_huge_pages());
  CHECK_FALSE(advised(bytes));
  CHECK_FALSE(advised(bytes + 3 * huge_page_advice_bytes));
  ::munmap(block, size);
}

TEST_CASE("a large array, made or copied, is advised before it is written; its numbers are zeros") {
  const std::size_t n = 2 * huge_page_advice_bytes / sizeof(double);
  Array a({n / 4, 4});
  CHECK(advised(a.data() + n / 2) == kernel_has_huge_pages());
  CHECK(std::all_of(a.ravel.begin(), a.ravel.end(), [](double v) { return v == 0; }));
  a.ravel[n - 1] = 5;
  const Array copy = a;
  CHECK(copy == a);
  CHECK(advised(copy.data() + n / 2) == kernel_has_huge_pages());
  Array assigned;
  assigned = a;
  CHECK(assigned == a);
  CHECK(advised(assigned.data() + n / 2) == kernel_has_huge_pages());
  // Assigned to itself, it stays as it was, in its own memory.
  const double* const before = assigned.data();
  const Array& itself = assigned;
  assigned = itself;
  CHECK(assigned == a);
  CHECK(assigned.data() == before);
  Array output;
  output.reshape_for_output({n});
  CHECK(output.size() == n);
  CHECK(advised(output.data() + n / 2) == kernel_has_huge_pages());
  const Array made = Array::for_output({n / 2, 2});
  CHECK(made.shape == std::vector<std::size_t>{n / 2, 2});
  CHECK(made.size() == n);
  CHECK(advised(made.data() + n / 2) == kernel_has_huge_pages());
}

TEST_CASE("assign_large copies into advised memory, or into the memory the vector has") {
  const std::size_t n = 2 * huge_page_advice_bytes / sizeof(double);
  Ravel from(n);
  for (std::size_t k = 0; k < n; ++k) from[k] = double(k);
  Ravel copy;
  assign_large(copy, from);
  CHECK(copy == from);
  CHECK(advised(copy.data() + n / 2) == kernel_has_huge_pages());
  // A copy that fits is written where the vector's numbers are.
  const double* const kept = copy.data();
  from[7] = -1;
  from.resize(n / 2);
  assign_large(copy, from);
  CHECK(copy == from);
  CHECK(copy.data() == kept);
  // A small block is copied as it is.
  const Ravel small(16, 2.5);
  Ravel small_copy;
  assign_large(small_copy, small);
  CHECK(small_copy == small);
}

TEST_CASE(
    "the tangents along a large grid's curves and stringers are advised before they are written") {
  // 300 x 300 points: 2.16 MB of tangents in each family.
  const int side = 300;
  Array points({std::size_t(side) * side, 3});
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      double* p = points.data() + 3 * (std::size_t(i) * side + j);
      p[0] = j, p[1] = i, p[2] = 0.01 * i * j;
    }
  const Array inptg({std::size_t(4) * side, 4});
  const GridTangents t = grid_tangents(side, side, as_vec3(points), inptg);
  REQUIRE(t.along_curves.size() * sizeof(Vec3) >= huge_page_advice_bytes);
  CHECK(advised(t.along_curves.data() + t.along_curves.size() / 2) == kernel_has_huge_pages());
  CHECK(advised(t.along_stringers.data() + t.along_stringers.size() / 2) ==
        kernel_has_huge_pages());
  // Along a curve of this grid x grows by 1 a point: the tangent's x is 1 inside.
  CHECK(t.along_curves[side / 2].x == doctest::Approx(1));
}

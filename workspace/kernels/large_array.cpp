#include "workspace/kernels/large_array.h"

#include <algorithm>
#include <cstdint>
#include <thread>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace igds {

namespace {

// Below this many doubles (8 MB) the ordinary allocation is as fast.
constexpr std::size_t large = std::size_t(1) << 20;

#ifdef __linux__
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23  // Linux 5.14; older kernels refuse it and the pages fault lazily
#endif
constexpr std::uintptr_t huge_page = std::uintptr_t(1) << 21;

void prepare(double* data, std::size_t doubles, unsigned threads) {
  const std::uintptr_t begin =
      (reinterpret_cast<std::uintptr_t>(data) + 4095) & ~std::uintptr_t(4095);
  const std::uintptr_t end =
      (reinterpret_cast<std::uintptr_t>(data + doubles)) & ~std::uintptr_t(4095);
  if (end <= begin) return;
  // Advice only: a refusal leaves the ordinary behaviour.
  madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  std::vector<std::thread> pool;
  auto populate = [](std::uintptr_t from, std::uintptr_t to) {
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
  };
  std::uintptr_t from = begin;
  for (unsigned t = 1; t <= threads; ++t) {
    std::uintptr_t to =
        t == threads ? end
                     : std::min(end, (begin + (end - begin) / threads * t) & ~(huge_page - 1));
    to = std::max(to, from);
    if (t == threads) {
      populate(from, to);
    } else {
      try {
        pool.emplace_back(populate, from, to);
      } catch (const std::system_error&) {
        populate(from, to);
      }
    }
    from = to;
  }
  for (auto& th : pool) th.join();
}
#else
void prepare(double*, std::size_t, unsigned) {}
#endif

}  // namespace

void advise_huge_pages([[maybe_unused]] const void* data, [[maybe_unused]] std::size_t bytes) {
#ifdef __linux__
  const std::uintptr_t page = 4096;
  const auto from = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
  const auto to = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
  if (to > from && to - from >= (std::uintptr_t(1) << 22))
    madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#endif
}

unsigned threads_for(std::size_t doubles) {
  if (doubles < large / 4) return 1;
  return std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
}

namespace {

// Room for n numbers in `ravel` (empty), prepared as large_array says when n is large.
void reserve_prepared(std::vector<double>& ravel, std::size_t n, unsigned threads) {
  if (n < large) return;
  ravel.reserve(n);
  prepare(ravel.data(), n, std::max(threads, 1u));
}

}  // namespace

Array large_array(std::vector<std::size_t> shape, unsigned threads) {
  Array a;
  const std::size_t n = Array::count(shape);
  a.shape = std::move(shape);
  reserve_prepared(a.ravel, n, threads);
  a.ravel.resize(n);
  return a;
}

Array large_copy(const Array& a, unsigned threads) {
  Array out;
  out.shape = a.shape;
  // The numbers written once, into the prepared room (not zeros first).
  reserve_prepared(out.ravel, a.size(), threads);
  out.ravel.assign(a.ravel.begin(), a.ravel.end());
  return out;
}

void reuse_for_output(Array& a, std::vector<std::size_t> shape, unsigned threads) {
  const std::size_t n = Array::count(shape);
  if (a.ravel.capacity() >= n && a.ravel.capacity() / 2 <= n) {
    a.shape = std::move(shape);
    a.ravel.resize(n);
  } else {
    // Free the old memory first: two large grids at once may not fit.
    a = Array{};
    a = large_array(std::move(shape), threads);
  }
}

}  // namespace igds

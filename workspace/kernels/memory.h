// The memory of large blocks (docs/decisions.md, "Memory"): glibc's, with the kernel asked to back
// a large block with huge pages before it is first written, so that its pages are faulted in
// 2 MB at a time instead of 4 KB, and written once, by what makes its numbers.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace igds {

// An allocator whose resize() leaves new elements unwritten: an output that overwrites every
// number is not written twice, and its pages are first touched by the threads that make it.
template <class T>
struct UnwrittenAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UnwrittenAllocator<U>;
  };
  UnwrittenAllocator() = default;
  template <class U>
  UnwrittenAllocator(const UnwrittenAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// Blocks that can hold a huge page (2 MB) are advised.
inline constexpr std::size_t huge_page_advice_bytes = std::size_t(2) << 20;

// Advises the kernel to back the whole pages of [p, p + bytes) with huge pages (madvise
// MADV_HUGEPAGE) when the block is large. Advice only: where the kernel has no transparent huge
// pages for the process, nothing changes.
void advise_huge_pages(const void* p, std::size_t bytes);

// Room for `n` elements in `v`, advised before anything is written in it.
template <class T, class A>
void reserve_large(std::vector<T, A>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
}

// `v` made a copy of `from`, its memory kept when it holds the copy, else new and advised.
template <class T, class A>
void assign_large(std::vector<T, A>& v, const std::vector<T, A>& from) {
  if (&v == &from) return;
  if (v.capacity() < from.size()) {
    v = std::vector<T, A>();
    reserve_large(v, from.size());
  }
  v.assign(from.begin(), from.end());
}

}  // namespace igds

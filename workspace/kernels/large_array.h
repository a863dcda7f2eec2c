// Arrays too large to be written in one sweep of cold memory: the output of the kernels.
#pragma once

#include <cstddef>
#include <vector>

#include "workspace/kernels/array.h"

namespace igds {

// A zero-filled Array of the given shape, like Array(shape), but when it is large its pages are
// first faulted in by `threads` threads at once, as transparent huge pages where the system allows
// (Linux): on a virtual machine faulting 4 KB pages one by one costs several times the writing.
Array large_array(std::vector<std::size_t> shape, unsigned threads);

// A copy of `a` in memory made ready as large_array's (huge pages, faulted in by `threads`).
Array large_copy(const Array& a, unsigned threads);

// Gives `a` the shape for an output that will be overwritten entirely: its memory is kept when it
// can hold the new array (and is not more than twice as large), so a recompute of the same size
// writes warm pages; otherwise `a` becomes large_array(shape, threads). The numbers it holds
// afterwards are unspecified.
void reuse_for_output(Array& a, std::vector<std::size_t> shape, unsigned threads);

// The number of threads worth using to write `doubles` numbers (1 below a few megabytes).
unsigned threads_for(std::size_t doubles);

// Asks for transparent huge pages over the whole pages of a large buffer that has not been
// written yet (a vector's reserved room), where the system allows (Linux): on a virtual machine
// each 4 KB page faulted in costs more than writing it. Advice only; nothing below 4 MB.
void advise_huge_pages(const void* data, std::size_t bytes);

// v.reserve(n), the room asked for as huge pages (a scratch buffer of a large drawing).
template <class V>
void reserve_large(V& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(*v.data()));
}

}  // namespace igds

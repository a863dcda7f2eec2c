// Splitting a loop over rows between a few threads (the machine's cores; writing large grids is
// memory-bound and one core does not saturate the memory).
#pragma once

#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace igds {

// Calls f(first, last) on `threads` contiguous slices of [0, count), one per thread, the first
// slice on the calling thread. If a thread cannot be started its slice runs here; an exception
// thrown by any slice is rethrown here once every thread has finished.
template <class F>
void parallel_for(std::size_t count, unsigned threads, const F& f) {
  if (threads <= 1 || count < 2) {
    f(std::size_t(0), count);
    return;
  }
  std::vector<std::exception_ptr> errors(threads);
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (unsigned t = 1; t < threads; ++t) {
    const std::size_t first = count * t / threads, last = count * (t + 1) / threads;
    auto slice = [&f, &errors, t, first, last] {
      try {
        f(first, last);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    };
    try {
      pool.emplace_back(slice);
    } catch (const std::system_error&) {
      slice();
    }
  }
  try {
    f(std::size_t(0), count / threads);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace igds
